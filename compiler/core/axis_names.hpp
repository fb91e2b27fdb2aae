// One axis of named values (core/precision.hpp, core/quality.hpp): its values and their names
// in axis order, and the look-ups every axis needs, written once.
#pragma once
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mb {

template <class T>
struct AxisNames {
  std::vector<T> values;
  std::vector<std::string> names;  // names[i] is the name of values[i]

  // From one {value, name} row per value, in axis order: a new value is one row.
  static AxisNames fromRows(std::initializer_list<std::pair<T, const char*>> rows) {
    AxisNames a;
    for (const auto& [v, n] : rows) {
      a.values.push_back(v);
      a.names.push_back(n);
    }
    return a;
  }

  const std::string& name(T v) const {
    for (size_t i = 0; i < values.size(); ++i)
      if (values[i] == v) return names[i];
    throw std::logic_error("AxisNames: a value without a name");
  }
  std::optional<T> parse(std::string_view n) const {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == n) return values[i];
    return std::nullopt;
  }
  // The names of `list`, in its order.
  std::vector<std::string> namesOf(const std::vector<T>& list) const {
    std::vector<std::string> out;
    for (T v : list) out.push_back(name(v));
    return out;
  }
  // Names already checked against `names`; throws std::invalid_argument for any other.
  std::vector<T> parseAll(const std::vector<std::string>& list, const std::string& what) const {
    std::vector<T> out;
    for (const auto& n : list) {
      auto v = parse(n);
      if (!v) throw std::invalid_argument("not a " + what + ": '" + n + "'");
      out.push_back(*v);
    }
    return out;
  }
};

}  // namespace mb
