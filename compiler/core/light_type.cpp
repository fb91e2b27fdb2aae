#include "core/light_type.hpp"

#include <algorithm>

#include "core/axis_names.hpp"

namespace mb {
namespace {

// The one list of light types, in axis order: a new type is one row here (and its enumerator),
// then its meaning where docs/architecture.md "Adding an axis value" lists.
const AxisNames<LightType>& lightTypeAxis() {
  static const AxisNames<LightType> a = AxisNames<LightType>::fromRows({
      {LightType::Dir, "dir"},
      {LightType::Point, "point"},
      {LightType::Spot, "spot"},
      {LightType::Sphere, "sphere"},
      {LightType::Tube, "tube"},
      {LightType::Rect, "rect"},
      {LightType::Disk, "disk"},
  });
  return a;
}

}  // namespace

const std::string& lightTypeName(LightType t) { return lightTypeAxis().name(t); }
const std::vector<LightType>& allLightTypes() { return lightTypeAxis().values; }
const std::vector<std::string>& allLightTypeNames() { return lightTypeAxis().names; }
std::optional<LightType> parseLightType(std::string_view name) { return lightTypeAxis().parse(name); }
std::vector<LightType> parseLightTypes(const std::vector<std::string>& names) {
  return lightTypeAxis().parseAll(names, "light type");
}
std::vector<std::string> lightTypeNames(const std::vector<LightType>& types) { return lightTypeAxis().namesOf(types); }

bool isLtcLight(LightType t) { return t == LightType::Rect || t == LightType::Disk; }
bool usesLtcTable(const std::vector<LightType>& types) { return std::any_of(types.begin(), types.end(), isLtcLight); }

std::vector<LightType> canonicalLights(std::vector<LightType> lights) {
  std::sort(lights.begin(), lights.end());
  lights.erase(std::unique(lights.begin(), lights.end()), lights.end());
  return lights;
}

}  // namespace mb
