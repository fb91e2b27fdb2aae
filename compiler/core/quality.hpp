// The quality axis of a permutation (docs/scenes.md "Quality"), as a type and one table of
// names. High is the model's default bindings; a model's manifest "quality" table, keyed by
// the other levels' names, says which bricks replace them (permute/specialize.hpp). The name
// is parsed once where it enters (the command line, a scene, a shard).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// In axis order, the order the command line and a scene's "expected one of" list them.
enum class Quality { Low, Medium, High };

const std::string& qualityName(Quality q);  // "low", "medium", "high"
// Every level, in axis order.
const std::vector<Quality>& allQualities();
// Their names, in the same order (what the command line and a scene accept).
const std::vector<std::string>& allQualityNames();
// nullopt for a name that is not a level.
std::optional<Quality> parseQuality(std::string_view name);
// Names already checked against allQualityNames() (by the command line or the scene loader);
// throws std::invalid_argument for any other name.
std::vector<Quality> parseQualities(const std::vector<std::string>& names);

}  // namespace mb
