#include "library/value_json.hpp"

namespace mb {

using nlohmann::json;

std::string formatNumber(double x) { return json(x).dump(); }

std::string formatRange(const Range& r) { return "[" + formatNumber(r.lo) + ", " + formatNumber(r.hi) + "]"; }

std::string jsonShapeOf(ValueType t) {
  if (t == ValueType::Float) return "a number";
  return "an array of " + std::to_string(componentCount(t)) + " numbers";
}

std::optional<std::vector<double>> readTypedValue(JsonFields& f, const std::string& ptr, ValueType t) {
  const json* j = f.find(ptr);
  if (!j) return std::nullopt;
  auto wrongShape = [&](const std::string& found) {
    f.error(
        "E-PARAM-TYPE", f.valueAt(ptr),
        "'" + JsonFields::describe(ptr) + "' must be a " + toString(t) + " (" + jsonShapeOf(t) + "), found " + found);
    return std::nullopt;
  };
  if (t == ValueType::Float) {
    if (!j->is_number()) return wrongShape(JsonFields::kindOf(*j));
    return std::vector<double>{j->get<double>()};
  }
  size_t n = static_cast<size_t>(componentCount(t));
  if (!j->is_array()) return wrongShape(JsonFields::kindOf(*j));
  if (j->size() != n) return wrongShape("an array of " + std::to_string(j->size()));
  std::vector<double> out;
  for (const auto& c : *j) {
    if (!c.is_number()) return wrongShape("an array containing a " + JsonFields::kindOf(c));
    out.push_back(c.get<double>());
  }
  return out;
}

bool checkInRange(JsonFields& f, const std::string& ptr, const std::vector<double>& value, const Range& range,
                  const std::string& rangeOrigin) {
  bool ok = true;
  bool isVector = f.find(ptr) && f.find(ptr)->is_array();
  for (size_t i = 0; i < value.size(); ++i) {
    if (value[i] >= range.lo && value[i] <= range.hi) continue;
    // Point at the offending component of a vector, so the column is exact.
    std::string at = isVector ? JsonFields::element(ptr, i) : ptr;
    f.error("E-PARAM-RANGE", f.valueAt(at),
            "'" + JsonFields::describe(at) + "' = " + formatNumber(value[i]) + " is outside " + formatRange(range) +
                ", " + rangeOrigin);
    ok = false;
  }
  return ok;
}

}  // namespace mb
