#include "core/json_fields.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace mb {

using nlohmann::json;

std::string JsonFields::member(const std::string& ptr, const std::string& key) {
  return ptr + "/" + JsonDocument::escape(key);
}

std::string JsonFields::element(const std::string& ptr, size_t index) { return ptr + "/" + std::to_string(index); }

static std::string unescapeToken(const std::string& t) {
  std::string out;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '~' && i + 1 < t.size()) {
      out += t[i + 1] == '1' ? '/' : '~';
      ++i;
    } else {
      out += t[i];
    }
  }
  return out;
}

std::string JsonFields::describe(const std::string& ptr) {
  if (ptr.empty()) return "(document)";
  std::string out;
  size_t pos = 1;
  while (pos <= ptr.size()) {
    size_t next = ptr.find('/', pos);
    if (next == std::string::npos) next = ptr.size();
    std::string token = unescapeToken(ptr.substr(pos, next - pos));
    // Pointers do not say whether a token is an index; all-digit tokens are, in our formats.
    bool index = !token.empty() && std::all_of(token.begin(), token.end(),
                                               [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
    if (index)
      out += "[" + token + "]";
    else
      out += (out.empty() ? "" : ".") + token;
    pos = next + 1;
  }
  return out;
}

std::string JsonFields::kindOf(const json& j) {
  if (j.is_number()) return "number";  // nlohmann distinguishes integer/float; users do not
  return j.type_name();
}

const json* JsonFields::find(const std::string& ptr) const {
  json::json_pointer p(ptr);
  if (!doc_.root().contains(p)) return nullptr;
  return &doc_.root().at(p);
}

void JsonFields::typeError(const std::string& ptr, const std::string& expected) {
  const json* j = find(ptr);
  std::string found = j ? kindOf(*j) : "nothing";
  error("E-FIELD-TYPE", valueAt(ptr), "'" + describe(ptr) + "' must be " + expected + ", found " + found);
}

bool JsonFields::object(const std::string& ptr, const std::vector<std::string>& required,
                        const std::vector<std::string>& optional, const std::string& what) {
  if (!isObject(ptr)) return false;
  const json& obj = *find(ptr);
  for (const auto& key : required) {
    if (!obj.contains(key)) error("E-MISSING-FIELD", valueAt(ptr), what + " is missing required field '" + key + "'");
  }
  std::vector<std::string> allowed = required;
  allowed.insert(allowed.end(), optional.begin(), optional.end());
  for (const auto& [key, value] : obj.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    error("E-UNKNOWN-FIELD", keyAt(member(ptr, key)),
          "unknown field '" + key + "' in " + what + " (known fields: " + quotedList(allowed) + ")",
          didYouMean(key, allowed));
  }
  return true;
}

bool JsonFields::isObject(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return false;
  if (!j->is_object()) {
    typeError(ptr, "an object");
    return false;
  }
  return true;
}

bool JsonFields::isArray(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return false;
  if (!j->is_array()) {
    typeError(ptr, "an array");
    return false;
  }
  return true;
}

std::optional<std::string> JsonFields::string(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return std::nullopt;
  if (!j->is_string()) {
    typeError(ptr, "a string");
    return std::nullopt;
  }
  return j->get<std::string>();
}

std::optional<double> JsonFields::number(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return std::nullopt;
  if (!j->is_number()) {
    typeError(ptr, "a number");
    return std::nullopt;
  }
  return j->get<double>();
}

std::optional<bool> JsonFields::boolean(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return std::nullopt;
  if (!j->is_boolean()) {
    typeError(ptr, "true or false");
    return std::nullopt;
  }
  return j->get<bool>();
}

std::optional<std::vector<std::string>> JsonFields::strings(const std::string& ptr) {
  if (!isArray(ptr)) return std::nullopt;
  std::vector<std::string> out;
  bool ok = true;
  const json& arr = *find(ptr);
  for (size_t i = 0; i < arr.size(); ++i) {
    auto s = string(element(ptr, i));
    if (s)
      out.push_back(*s);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

std::optional<std::pair<double, double>> JsonFields::range(const std::string& ptr) {
  const json* j = find(ptr);
  if (!j) return std::nullopt;
  if (!j->is_array() || j->size() != 2 || !(*j)[0].is_number() || !(*j)[1].is_number()) {
    typeError(ptr, "a [lo, hi] array of two numbers");
    return std::nullopt;
  }
  double lo = (*j)[0].get<double>(), hi = (*j)[1].get<double>();
  if (!(lo <= hi)) {
    error("E-PARAM-RANGE", valueAt(ptr),
          "'" + describe(ptr) + "' is an empty range: lo " + (*j)[0].dump() + " > hi " + (*j)[1].dump());
    return std::nullopt;
  }
  return std::make_pair(lo, hi);
}

std::string quotedList(const std::vector<std::string>& names) {
  if (names.empty()) return "(none)";
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

bool isIdentifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

}  // namespace mb
