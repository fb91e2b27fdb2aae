#include "emit/light_contract.hpp"

#include <stdexcept>

namespace mb {

std::string lightStructName(LightType t) {
  switch (t) {
    case LightType::Dir:
      return "DirectionalLight";
    case LightType::Point:
      return "PointLight";
    case LightType::Spot:
      return "SpotLight";
    case LightType::Sphere:
      return "SphereLight";
    case LightType::Tube:
      return "TubeLight";
    case LightType::Rect:
      return "RectLight";
    case LightType::Disk:
      return "DiskLight";
  }
  throw std::logic_error("lightStructName: a light type without a GLSL struct");
}

std::string lightEntryPoint(LightType t) { return "shade" + lightStructName(t); }

}  // namespace mb
