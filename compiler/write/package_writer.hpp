// write: a package directory, atomically. Everything is staged in a temporary sibling
// directory and renamed into place at the end, so a failure never leaves a partial package.
#pragma once
#include <filesystem>
#include <functional>
#include <ostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mb {

class PackageWriter {
 public:
  // `kind` goes into the directory's marker (write/output_paths.hpp): "package", "bench".
  explicit PackageWriter(std::string kind = "package") : kind_(std::move(kind)) {}
  // Removes the staging directory of a streaming writer that was never committed.
  ~PackageWriter();
  PackageWriter(const PackageWriter&) = delete;
  PackageWriter& operator=(const PackageWriter&) = delete;

  // Streaming: checks `dir` as commit does, then creates the staging directory beside it and
  // its marker; from then on every file goes straight to disk, so memory does not grow with
  // the package. Without it, files are kept in memory until commit. Throws DiagnosticError.
  void stage(const std::filesystem::path& dir);
  void addFile(const std::string& relativePath, std::string bytes);
  void addFile(const std::string& relativePath, const std::vector<uint32_t>& words);
  // A large file written piece by piece (the manifest of 10^5 permutations).
  void addFileStreamed(const std::string& relativePath, const std::function<void(std::ostream&)>& write);
  // Writes all files and the marker to `dir` (the staged one, when streaming): creates it,
  // fills it when empty, or replaces it in one atomic step when it carries the marker
  // (E-OUTPUT-NOT-PACKAGE otherwise). Temporaries a killed run left beside it are removed
  // first. Throws DiagnosticError on I/O failure, leaving `dir` as it was.
  void commit(const std::filesystem::path& dir);
  // Writes one file via a temporary sibling and a rename (replaceFileAtomically); throws
  // DiagnosticError (E-IO) when that fails.
  static void writeFileAtomically(const std::filesystem::path& file, const std::string& bytes);

 private:
  std::string kind_;
  std::map<std::string, std::string> files_;
  std::filesystem::path staging_;  // streaming: where files go; empty otherwise
  std::filesystem::path stagedFor_;
  size_t streamed_ = 0;
};

// Writes `bytes` to a temporary sibling of `file` whose name no other writer uses (process id,
// thread id, a counter), then rename(2)s it over `file`: a reader sees the old file, the new
// one or none, never a partial one. False (and no temporary left) on any I/O failure.
bool replaceFileAtomically(const std::filesystem::path& file, const std::string& bytes);

// 64-bit xxHash of bytes, as 16 hex digits.
std::string contentHash(const void* data, size_t size);

}  // namespace mb
