#include "core/value_type.hpp"

namespace mb {

int componentCount(ValueType t) {
  switch (t) {
    case ValueType::Float:
      return 1;
    case ValueType::Vec2:
      return 2;
    case ValueType::Vec3:
      return 3;
    case ValueType::Geometry:
      return 9;  // the probe passes n, v, l (DESIGN.md "Inputs are vectors")
  }
  return 0;
}

std::string toString(ValueType t) {
  switch (t) {
    case ValueType::Float:
      return "float";
    case ValueType::Vec2:
      return "vec2";
    case ValueType::Vec3:
      return "vec3";
    case ValueType::Geometry:
      return "Geometry";
  }
  return "?";
}

std::optional<ValueType> parseValueType(const std::string& s) {
  // Exact spelling only: these names appear verbatim in GLSL signatures.
  for (ValueType t : {ValueType::Float, ValueType::Vec2, ValueType::Vec3, ValueType::Geometry})
    if (toString(t) == s) return t;
  return std::nullopt;
}

}  // namespace mb
