// The precision axis of a permutation (docs/models.md "Permutation axes"), as a type and one
// table of names. The name is parsed once where it enters (the command line, a scene, a
// shard); a Permutation holds the value, and its name appears only in keys, file names and
// JSON. emit/precision.hpp maps it to what the emitter writes (ShaderPrecision).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// In axis order: the order the command line, the scene's "expected one of" and the
// --explain counts list them.
enum class Precision { Fp32, Fp16 };

const std::string& precisionName(Precision p);  // "fp32", "fp16"
// Every precision, in axis order.
const std::vector<Precision>& allPrecisions();
// Their names, in the same order (what the command line and a scene accept).
const std::vector<std::string>& allPrecisionNames();
// nullopt for a name that is not a precision.
std::optional<Precision> parsePrecision(std::string_view name);
// Names already checked against allPrecisionNames() (by the command line or the scene loader);
// throws std::invalid_argument for any other name.
std::vector<Precision> parsePrecisions(const std::vector<std::string>& names);

}  // namespace mb
