#include "core/quality.hpp"

#include "core/axis_names.hpp"

namespace mb {
namespace {

const AxisNames<Quality>& qualityAxis() {
  static const AxisNames<Quality> a{{Quality::Low, Quality::Medium, Quality::High}, {"low", "medium", "high"}};
  return a;
}

}  // namespace

const std::string& qualityName(Quality q) { return qualityAxis().name(q); }
const std::vector<Quality>& allQualities() { return qualityAxis().values; }
const std::vector<std::string>& allQualityNames() { return qualityAxis().names; }
std::optional<Quality> parseQuality(std::string_view name) { return qualityAxis().parse(name); }
std::vector<Quality> parseQualities(const std::vector<std::string>& names) {
  return qualityAxis().parseAll(names, "quality level");
}

}  // namespace mb
