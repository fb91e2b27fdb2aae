#include "load/project_files.hpp"

#include <algorithm>
#include <cctype>

namespace mb {

namespace fs = std::filesystem;

std::optional<std::string> readTextFile(const std::string& path, const SourceLocation& at, const InputKind& kind,
                                        DiagnosticSink& sink) {
  InputFileError error;
  auto text = readInputFile(path, kind, error);
  if (!text) sink.error(error.code, at, error.message);
  return text;
}

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string readMaterialFile(const std::string& path, const InputKind& kind) {
  return readInputFileOrThrow(path, kind);
}

namespace {

fs::path absoluteNormal(const fs::path& p) {
  std::error_code ec;
  fs::path a = fs::absolute(p, ec);
  return (ec ? p : a).lexically_normal();
}

// True when `p` (absolute, normalized) lies in `dir` (absolute, normalized).
bool inside(const fs::path& p, const fs::path& dir) {
  fs::path rel = p.lexically_relative(dir);
  return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

ProjectFiles::ProjectFiles(const std::string& topFile) : dir_(absoluteNormal(fs::path(topFile)).parent_path()) {}

std::optional<std::string> ProjectFiles::resolve(const std::string& written, const std::string& fromFile,
                                                 const SourceLocation& at, DiagnosticSink& sink) const {
  fs::path w(written);
  if (written.empty()) {
    sink.error("E-PATH-ESCAPE", at, "empty path: expected a file relative to the including file");
    return std::nullopt;
  }
  if (w.is_absolute() || w.has_root_name() || w.has_root_directory()) {
    sink.error("E-PATH-ESCAPE", at,
               "absolute path '" + written +
                   "': expected a path relative to the including file, inside the "
                   "project directory '" +
                   dir_.string() + "'");
    return std::nullopt;
  }
  fs::path shown = (fs::path(fromFile).parent_path() / w).lexically_normal();
  fs::path full = absoluteNormal(shown);
  bool ok = inside(full, dir_);
  // A symbolic link inside the project may still point out of it.
  std::error_code ec;
  if (ok && fs::exists(full, ec)) {
    fs::path real = fs::weakly_canonical(full, ec);
    fs::path realDir = fs::weakly_canonical(dir_, ec);
    if (!ec) ok = inside(real, realDir);
  }
  if (!ok) {
    sink.error("E-PATH-ESCAPE", at,
               "'" + written + "' leaves the project directory '" + dir_.string() +
                   "': includes and surface files must lie in the directory of the top-level material "
                   "file or below it");
    return std::nullopt;
  }
  return shown.string();
}

}  // namespace mb
