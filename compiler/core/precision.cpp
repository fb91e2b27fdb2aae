#include "core/precision.hpp"

#include <stdexcept>

namespace mb {

const std::vector<Precision>& allPrecisions() {
  static const std::vector<Precision> v{Precision::Fp32, Precision::Fp16};
  return v;
}

const std::vector<std::string>& allPrecisionNames() {
  static const std::vector<std::string> v{"fp32", "fp16"};
  return v;
}

const std::string& precisionName(Precision p) { return allPrecisionNames().at(static_cast<size_t>(p)); }

std::optional<Precision> parsePrecision(std::string_view name) {
  for (Precision p : allPrecisions())
    if (name == precisionName(p)) return p;
  return std::nullopt;
}

std::vector<Precision> parsePrecisions(const std::vector<std::string>& names) {
  std::vector<Precision> out;
  for (const auto& n : names) {
    auto p = parsePrecision(n);
    if (!p) throw std::invalid_argument("not a precision: '" + n + "'");
    out.push_back(*p);
  }
  return out;
}

}  // namespace mb
