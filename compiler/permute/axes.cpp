// INTERIM (replaced by the validity rules).
#include "permute/axes.hpp"

namespace mb {

const std::vector<std::string>& allPrecisions() {
  static const std::vector<std::string> v{"fp32", "fp16"};
  return v;
}
const std::vector<std::string>& allQualityLevels() {
  static const std::vector<std::string> v{"low", "medium", "high"};
  return v;
}
std::optional<std::string> invalidReason(const ShadingModel&, const AxisPoint&) { return std::nullopt; }
std::optional<std::string> invalidReason(const ShadingModel&, const Permutation&) { return std::nullopt; }
std::vector<AxisSize> axisSizes(const ShadingModel&) { return {}; }
size_t validCombinationCount(const ShadingModel&) { return 0; }

}  // namespace mb
