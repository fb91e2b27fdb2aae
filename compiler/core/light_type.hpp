// The light types a permutation shades (docs/models.md "Permutation axes"), as a type and one
// table of names. A name is parsed once where it enters (the command line, a scene, a glTF
// file's KHR_lights_punctual, a shard, a model's manifest); a Permutation holds the values, and
// their names appear only in keys, file names, JSON and the MB_LIGHT_<NAME> defines. Which
// types a model shades is the library's data (its manifest's "lights"); the types themselves
// are the compiler's, since the emitter, the probe scene and the preview give each its light
// record (emit/light_contract.hpp; docs/architecture.md "Adding an axis value").
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// In axis order: the order a permutation's key, the command line and a scene's "expected one
// of" list them. canonicalLights() sorts by the enumerators' order, so a new type goes here and
// in light_type.cpp's table at the same place.
enum class LightType { Dir, Point, Spot, Sphere, Tube, Rect, Disk };

const std::string& lightTypeName(LightType t);  // "dir", "point", "spot", "sphere", "tube", "rect", "disk"
// Every type, in axis order.
const std::vector<LightType>& allLightTypes();
// Their names, in the same order (what the command line, a scene and a manifest accept).
const std::vector<std::string>& allLightTypeNames();
// nullopt for a name that is not a light type.
std::optional<LightType> parseLightType(std::string_view name);
// Names already checked against allLightTypeNames(); throws std::invalid_argument for any other.
std::vector<LightType> parseLightTypes(const std::vector<std::string>& names);
// The names of `types`, in their order (messages, keys, JSON).
std::vector<std::string> lightTypeNames(const std::vector<LightType>& types);

// Rectangle and disk lights: given by luminance and shaded with the LTC table
// (docs/models/lights.md "Rectangle and disk lights"); a set that has one needs the table.
bool isLtcLight(LightType t);
bool usesLtcTable(const std::vector<LightType>& types);
// The light method (a model's "lightMethods", docs/models.md) whose lights read the LTC table:
// sphere and tube lights shaded by linearly transformed cosines.
inline constexpr std::string_view kLtcLightMethod = "ltc";

// Sorts light types into axis order and drops duplicates: a scene's lights (load/), a
// permutation's and its key (permute/) all use this one order.
std::vector<LightType> canonicalLights(std::vector<LightType> lights);

}  // namespace mb
