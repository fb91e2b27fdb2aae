#include "core/glsl_float.hpp"

#include <charconv>
#include <cstdio>

namespace mb {

std::string glslFloat(double value, FloatDigits digits) {
  char buf[64];
  std::string s;
  if (digits == FloatDigits::Shortest) {
    auto res = std::to_chars(buf, buf + sizeof buf, static_cast<float>(value));
    s.assign(buf, res.ptr);
  } else {
    std::snprintf(buf, sizeof buf, "%.9g", value);
    s = buf;
  }
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "1" -> "1.0"; "inf", "nan" as they are
  return s;
}

}  // namespace mb
