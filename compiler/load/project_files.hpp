// Files a material description reads besides itself (macro-form #include, a JSON surface
// `file`), and the rule that keeps them inside the project: the directory that holds the
// top-level material file (docs/macro-form.md "Includes and the project directory").
#pragma once
#include <filesystem>
#include <optional>
#include <string>

#include "core/diagnostics.hpp"
#include "core/input_file.hpp"

namespace mb {

// Reads a whole text file (core/input_file.hpp). Reports E-FILE-NOT-FOUND (missing or
// unreadable), E-FILE-NOT-REGULAR (a directory, FIFO or device must not hang the loader) or
// E-FILE-TOO-LARGE (over the kind's limit) at `at`.
std::optional<std::string> readTextFile(const std::string& path, const SourceLocation& at, const InputKind& kind,
                                        DiagnosticSink& sink);

// A top-level description file's text; throws DiagnosticError at the file when it cannot be read.
std::string readMaterialFile(const std::string& path, const InputKind& kind);

// The extension of `path` in lower case (".json", ".glb"): description forms are picked by it.
std::string lowerExtension(const std::string& path);

class ProjectFiles {
 public:
  // `topFile`: the material file named on the command line; its directory is the project.
  explicit ProjectFiles(const std::string& topFile);

  // The path of `written` (as written in `fromFile`, relative to fromFile's directory), for
  // reading and for diagnostics. An absolute path, or one that leaves the project directory
  // (by `..` or through a symbolic link), is E-PATH-ESCAPE at `at`.
  std::optional<std::string> resolve(const std::string& written, const std::string& fromFile, const SourceLocation& at,
                                     DiagnosticSink& sink) const;

  const std::filesystem::path& directory() const { return dir_; }

 private:
  std::filesystem::path dir_;  // absolute, normalized
};

}  // namespace mb
