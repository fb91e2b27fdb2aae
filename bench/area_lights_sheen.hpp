// The sheen lobe (Charlie D, Ashikhmin V: the standard model's sheen defaults) under area lights
// by linearly transformed cosines fitted to it (shaderlib/ltc/charlie.json), plain and with the
// residual's quadrature as a control variate (the *_ltc_sheen_cv bricks), beside what the model
// did before it: the lobe at the light centre's direction times the light's exact irradiance.
// Against the lobe integrated adaptively over the light (common/ltc_reference.hpp), in double;
// sheen roughness 0.05 to 1, n.v 0.05 to 1, the lights drawn as area_lights_ltc.cpp draws them.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "ltc/ltc_table.hpp"

namespace mb::bench {

// `samples` configurations per shape (sphere, tube, rect, disk).
nlohmann::json measureLtcSheen(const ltc::Table& sheenTable, int samples, uint64_t seed);

// The section's table as Markdown (docs/models/lights.md).
std::string ltcSheenMarkdown(const nlohmann::json& section);

}  // namespace mb::bench
