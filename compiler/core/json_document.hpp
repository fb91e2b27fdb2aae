// JSON with source positions. nlohmann-json parses (and reports syntax errors with a byte
// offset); a small scanner then walks the already-valid text and the parsed tree together and
// records where every object member's key and value start. The table is compact (16 bytes per
// member, keyed by the member's node in the tree; array elements are found from their array) and line:column is worked out only when asked
// for, so a document costs about its tree plus its text (docs/formats.md "Input memory").
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/input_file.hpp"

namespace mb {

class JsonDocument {
 public:
  // Parses `text` (read from `file`). Syntax errors, and nesting deeper than `maxDepth`, throw
  // DiagnosticError (code E-JSON-SYNTAX). Real files stay far below the default (a glTF
  // scene ~10 levels). More than `maxValues` values is E-FILE-TOO-LARGE, found before the tree
  // is built: a kind whose real files are small (a material) bounds its tree, which costs up
  // to ~100 bytes per value. The document keeps the text (for positions); pass it by move to
  // keep a single copy.
  static JsonDocument parse(std::string text, const std::string& file, int maxDepth = 256, size_t maxValues = SIZE_MAX);
  // Reads (core/input_file.hpp: regular files only, at most the kind's limit) and parses a
  // file. A file that cannot be read throws DiagnosticError (E-FILE-NOT-FOUND,
  // E-FILE-NOT-REGULAR, E-FILE-TOO-LARGE).
  static JsonDocument load(const std::string& path, const InputKind& kind = input_kind::kJson);

  JsonDocument() = default;
  JsonDocument(JsonDocument&&) noexcept = default;
  JsonDocument& operator=(JsonDocument&&) noexcept = default;
  // A copy's table is rebuilt for the copied tree's nodes.
  JsonDocument(const JsonDocument& other);
  JsonDocument& operator=(const JsonDocument& other);

  const nlohmann::json& root() const { return root_; }
  const std::string& file() const { return file_; }
  // Location of the value at `pointer` (e.g. "/bricks/specular_d"), or of the nearest
  // enclosing value that has one.
  SourceLocation valueAt(const std::string& pointer) const;
  // Location of the key string of the member at `pointer`; falls back to valueAt.
  SourceLocation keyAt(const std::string& pointer) const;

  // Escapes one reference token per RFC 6901.
  static std::string escape(const std::string& token);

  // Where the value of one object member starts, and its key. Array elements have none: their
  // positions are found from their array's (elementOffset).
  struct Position {
    const nlohmann::json* node;
    uint32_t value;
    uint32_t key;
  };
  static constexpr uint32_t kNoOffset = UINT32_MAX;

 private:
  // Where the deepest value on `pointer`'s path that exists starts (and its key), and
  // whether that is the whole path.
  struct Found {
    uint32_t value, key;
    bool whole;
  };
  Found find(const std::string& pointer) const;
  // Where element `index` of the array whose '[' is at `array` starts: found by skipping the
  // elements before it in the (valid) text.
  uint32_t elementOffset(uint32_t array, size_t index) const;
  const Position* positionOf(const nlohmann::json* node) const;
  SourceLocation locationOf(uint32_t offset) const;

  nlohmann::json root_;
  std::string file_;
  std::string text_;
  uint32_t rootOffset_ = 0;
  std::vector<Position> positions_;  // object members, sorted by node address
  // Per 4 KiB block of the text: newlines before it, and the offset after the last one.
  std::vector<uint32_t> blockLines_, blockLineStart_;
};

// Converts a byte offset into 1-based line and column.
SourceLocation locationOfOffset(const std::string& text, size_t offset, const std::string& file);

// Scanning valid JSON text without parsing it (the position scan above, the glTF container's
// filtering): past whitespace from i, and from the start of a value to just past it.
size_t skipJsonSpace(const std::string& text, size_t i);
size_t skipJsonValue(const std::string& text, size_t i);

}  // namespace mb
