// Reading typed values (a float, or a vec2/vec3 as an array) and ranges out of JSON, shared
// by the model inputs of the library and the parameters of a material so both report the
// same codes (E-PARAM-TYPE, E-PARAM-RANGE) with the same wording.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/json_fields.hpp"
#include "library/shader_library.hpp"

namespace mb {

// Expected JSON shape of a value of `t`, for messages: "a number", "an array of 3 numbers".
std::string jsonShapeOf(ValueType t);

// The value at `ptr` as `t` (float: a number; vecN: an array of N numbers). A wrong shape
// reports E-PARAM-TYPE at the value. Absent: nothing, silently.
std::optional<std::vector<double>> readTypedValue(JsonFields& f, const std::string& ptr, ValueType t);

// Reports E-PARAM-RANGE for each component of `value` (read from `ptr`) outside `range`.
// `rangeOrigin` says where the range came from, e.g. "the range of model input 'roughness'".
bool checkInRange(JsonFields& f, const std::string& ptr, const std::vector<double>& value, const Range& range,
                  const std::string& rangeOrigin);

// "[0.0, 1.0]"; numbers printed as JSON prints them, so messages echo the file.
std::string formatRange(const Range& r);
std::string formatNumber(double x);

}  // namespace mb
