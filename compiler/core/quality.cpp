#include "core/quality.hpp"

#include "core/axis_names.hpp"

namespace mb {
namespace {

const AxisNames<Quality>& axis() {
  static const AxisNames<Quality> a{{Quality::Low, Quality::Medium, Quality::High}, {"low", "medium", "high"}};
  return a;
}

}  // namespace

const std::string& qualityName(Quality q) { return axis().name(q); }
const std::vector<Quality>& allQualities() { return axis().values; }
const std::vector<std::string>& allQualityNames() { return axis().names; }
std::optional<Quality> parseQuality(std::string_view name) { return axis().parse(name); }
std::vector<Quality> parseQualities(const std::vector<std::string>& names) {
  return axis().parseAll(names, "quality level");
}

}  // namespace mb
