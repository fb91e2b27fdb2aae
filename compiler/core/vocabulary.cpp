#include "core/vocabulary.hpp"

namespace mb {

const std::vector<std::string>& allPrecisions() {
  static const std::vector<std::string> v{"fp32", "fp16"};
  return v;
}

const std::vector<std::string>& allQualityLevels() {
  static const std::vector<std::string> v{"low", "medium", "high"};
  return v;
}

const std::vector<std::string>& allTargets() {
  static const std::vector<std::string> t{"spirv", "glsl450", "essl310", "hlsl", "msl"};
  return t;
}

}  // namespace mb
