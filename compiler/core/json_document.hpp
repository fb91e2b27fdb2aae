// JSON with source positions. nlohmann-json parses (and reports syntax errors with a byte
// offset); a small scanner over the already-valid text then records where every value
// and every object key starts, keyed by JSON pointer, so later stages can report
// file:line:column for semantic errors too.
#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "core/diagnostics.hpp"

namespace mb {

class JsonDocument {
 public:
  // Parses `text` (read from `file`). Syntax errors, and nesting deeper than `maxDepth`, throw
  // DiagnosticError (code E-JSON-SYNTAX). Real files stay far below the default (a glTF
  // scene ~10 levels).
  static JsonDocument parse(const std::string& text, const std::string& file, int maxDepth = 256);
  // Reads and parses a file. A missing file throws DiagnosticError (code E-FILE-NOT-FOUND).
  static JsonDocument load(const std::string& path);

  const nlohmann::json& root() const { return root_; }
  const std::string& file() const { return file_; }
  // Location of the value at `pointer` (e.g. "/bricks/specular_d"), or of the nearest
  // enclosing value that has one.
  SourceLocation valueAt(const std::string& pointer) const;
  // Location of the key string of the member at `pointer`; falls back to valueAt.
  SourceLocation keyAt(const std::string& pointer) const;

  // Escapes one reference token per RFC 6901.
  static std::string escape(const std::string& token);

 private:
  nlohmann::json root_;
  std::string file_;
  std::map<std::string, SourceLocation> values_;
  std::map<std::string, SourceLocation> keys_;
};

// Converts a byte offset into 1-based line and column.
SourceLocation locationOfOffset(const std::string& text, size_t offset, const std::string& file);

}  // namespace mb
