#include "compile/hlsl_spirv.hpp"

#include <sstream>

namespace mb {

std::string hlslWithInputLocations(const std::string& hlsl) {
  std::istringstream in(hlsl);
  std::ostringstream out;
  std::string line;
  bool inInputs = false;
  while (std::getline(in, line)) {
    if (line.rfind("struct SPIRV_Cross_Input", 0) == 0) inInputs = true;
    if (inInputs && line.rfind("};", 0) == 0) inInputs = false;
    const std::string semantic = " : TEXCOORD";
    const size_t at = line.find(semantic);
    if (inInputs && at != std::string::npos && line.back() == ';') {
      const std::string number = line.substr(at + semantic.size(), line.size() - 1 - at - semantic.size());
      const size_t indent = line.find_first_not_of(' ');
      if (!number.empty() && number.find_first_not_of("0123456789") == std::string::npos && indent != std::string::npos)
        line = line.substr(0, indent) + "[[vk::location(" + number + ")]] " + line.substr(indent);
    }
    out << line << '\n';
  }
  return out.str();
}

}  // namespace mb
