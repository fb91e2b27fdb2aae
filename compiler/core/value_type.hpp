// The few value types that appear in slot signatures. `Geometry` is special: a brick
// receives the Geometry struct, but its probe (and the reference) receive the *vectors*
// n, v, l and build the dot products themselves, as a real shader does (DESIGN.md,
// "Inputs are vectors").
#pragma once
#include <optional>
#include <string>

namespace mb {

enum class ValueType { Float, Vec2, Vec3, Geometry };

// Number of floats the value occupies in a probe's input or output record.
int componentCount(ValueType t);
std::string toString(ValueType t);  // "float", "vec2", "vec3", "Geometry"
std::optional<ValueType> parseValueType(const std::string& s);

}  // namespace mb
