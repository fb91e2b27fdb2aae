// Shared by the glTF import tests: running the import on inline text and checking a
// diagnostic's position against the text itself.
#pragma once
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "load/gltf_import.hpp"
#include "material_fixtures.hpp"  // diagnosticsOf, theOne
#include "pipeline_support.hpp"   // shippedLibrary

namespace mb::test {

// All diagnostics of parsing `bytes` as `file` (empty if it parses).
inline std::vector<Diagnostic> gltfDiagnostics(const std::string& bytes, const std::string& file = "t.gltf") {
  return diagnosticsOf([&] { parseGltf(bytes, file, shippedLibrary()); });
}

// 1-based line and column of the first occurrence of `needle` in `text` (after `after`).
inline std::pair<int, int> positionOf(const std::string& text, const std::string& needle,
                                      const std::string& after = "") {
  size_t from = after.empty() ? 0 : text.find(after);
  REQUIRE(from != std::string::npos);
  size_t at = text.find(needle, from);
  REQUIRE(at != std::string::npos);
  int line = 1, column = 1;
  for (size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

inline void requireAt(const SourceLocation& where, std::pair<int, int> lineColumn) {
  INFO(where.file << ":" << where.line << ":" << where.column);
  CHECK(where.line == lineColumn.first);
  CHECK(where.column == lineColumn.second);
}

inline void requireAt(const Diagnostic& d, std::pair<int, int> lineColumn) {
  INFO(formatDiagnostic(d));
  requireAt(d.where, lineColumn);
}

// A file in the temporary directory for the life of the object.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& bytes)
      : path_(std::filesystem::temp_directory_path() / ("mb_gltf_" + std::to_string(::getpid()) + "_" + name)) {
    std::ofstream(path_, std::ios::binary) << bytes;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace mb::test
