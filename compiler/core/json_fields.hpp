// Typed, position-aware reads of a JsonDocument for the loaders (library manifest, material
// JSON). Every accessor reports a problem at the exact key or value and returns "nothing"
// instead of throwing, so a loader can carry on and report every error in a file at once.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/json_document.hpp"

namespace mb {

class JsonFields {
 public:
  JsonFields(const JsonDocument& doc, DiagnosticSink& sink) : doc_(doc), sink_(sink) {}

  const JsonDocument& doc() const { return doc_; }
  DiagnosticSink& sink() { return sink_; }

  // JSON pointer of a member / element of the value at `ptr`.
  static std::string member(const std::string& ptr, const std::string& key);
  static std::string element(const std::string& ptr, size_t index);
  // Readable path for messages: "/parameters/roughness/range/0" -> "parameters.roughness.range[0]".
  static std::string describe(const std::string& ptr);
  // The JSON type name nlohmann uses ("number", "string", ...), for "found ..." messages.
  static std::string kindOf(const nlohmann::json& j);

  // The value at `ptr`, or nullptr when absent.
  const nlohmann::json* find(const std::string& ptr) const;
  SourceLocation keyAt(const std::string& ptr) const { return doc_.keyAt(ptr); }
  SourceLocation valueAt(const std::string& ptr) const { return doc_.valueAt(ptr); }

  // Checks the object at `ptr`: E-FIELD-TYPE (and false) if it is not an object, then
  // E-MISSING-FIELD for each absent required key (at the object, since the key has no
  // position) and E-UNKNOWN-FIELD for each key outside `required` + `optional` (at the key,
  // with a did-you-mean over the allowed keys). `what` names the object in messages.
  bool object(const std::string& ptr, const std::vector<std::string>& required,
              const std::vector<std::string>& optional, const std::string& what);

  // Type checks of the value at `ptr`. An absent value yields nothing *silently*: `object`
  // has already reported it if it was required. A value of the wrong JSON type reports
  // E-FIELD-TYPE at the value.
  bool isObject(const std::string& ptr);
  bool isArray(const std::string& ptr);
  std::optional<std::string> string(const std::string& ptr);
  std::optional<double> number(const std::string& ptr);
  std::optional<bool> boolean(const std::string& ptr);
  std::optional<std::vector<std::string>> strings(const std::string& ptr);
  // A [lo, hi] pair of numbers. lo > hi is reported as E-PARAM-RANGE.
  std::optional<std::pair<double, double>> range(const std::string& ptr);

  void typeError(const std::string& ptr, const std::string& expected);
  void error(std::string code, const SourceLocation& where, std::string message, std::string suggestion = {}) {
    sink_.error(std::move(code), where, std::move(message), std::move(suggestion));
  }

 private:
  const JsonDocument& doc_;
  DiagnosticSink& sink_;
};

// [A-Za-z_][A-Za-z0-9_]*: names that end up as GLSL / C++ identifiers.
bool isIdentifier(const std::string& s);

// "'a', 'b', 'c'" (or "(none)"), for "expected one of ..." messages.
std::string quotedList(const std::vector<std::string>& names);

}  // namespace mb
