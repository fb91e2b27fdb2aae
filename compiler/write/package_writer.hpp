// write: a package directory, atomically. Everything is staged in a temporary sibling
// directory and renamed into place at the end, so a failure never leaves a partial package.
// The directory's marker (write/output_marker.hpp) lists every file written, with its size
// and hash; replacing an output removes only what its marker lists (docs/cli.md "Outputs").
#pragma once
#include <filesystem>
#include <functional>
#include <ostream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/content_hash.hpp"  // the marker records each file's contentHash
#include "write/output_marker.hpp"
#include "write/spill_file.hpp"

namespace mb {

class PackageWriter {
 public:
  // `kind` goes into the directory's marker (write/output_paths.hpp): "package", "bench".
  explicit PackageWriter(std::string kind = "package");
  // Removes the staging directory of a streaming writer that was never committed.
  ~PackageWriter();
  PackageWriter(const PackageWriter&) = delete;
  PackageWriter& operator=(const PackageWriter&) = delete;

  // Streaming: checks `dir` as commit does, then creates the staging directory beside it and
  // its marker; from then on every file goes straight to disk, so memory does not grow with
  // the package (the marker's file list goes to a SpillFile). Without it, files are kept in
  // memory until commit. A symlink `dir` stands for the directory it points to. Throws
  // DiagnosticError.
  void stage(const std::filesystem::path& dir);
  // `relativePath` is plain components ("spirv/ab.spv"): an absolute path, "..", "." or the
  // marker's name is E-OUTPUT-NAME.
  void addFile(const std::string& relativePath, std::string bytes);
  void addFile(const std::string& relativePath, const std::vector<uint32_t>& words);
  // A large file written piece by piece (the manifest of 10^5 permutations).
  void addFileStreamed(const std::string& relativePath, const std::function<void(std::ostream&)>& write);
  // Writes all files and the marker to `dir` (the staged one, when streaming): creates it,
  // fills it when empty, or replaces it in one atomic step when it holds only what its marker
  // lists (checkOutputDirectory; refused otherwise), then removes the old output's listed
  // files. Temporaries a killed run left beside it are removed first. Throws DiagnosticError
  // on I/O failure, leaving `dir` as it was.
  void commit(const std::filesystem::path& dir);
  // Writes one file the user named: via a marked temporary directory beside it
  // (".<name>.matbricks-tmp.<pid>.<n>", removed by the next write when a kill left it) and a
  // rename; throws DiagnosticError (E-IO) when that fails. matbricks' own cache files go
  // through replaceFileAtomically (core/atomic_file.hpp) instead.
  static void writeFileAtomically(const std::filesystem::path& file, const std::string& bytes);

 private:
  std::string kind_;
  void record(const std::string& relativePath, const MarkedFile& file);
  void writeInto(const std::filesystem::path& staging, const std::string& relativePath,
                 const std::function<void(std::ostream&)>& write);
  void finishMarker(const std::filesystem::path& staging);

  std::map<std::string, std::string> files_;
  std::unique_ptr<SpillFile> records_;  // the marker's file lines, in write order
  uint64_t recordCount_ = 0;
  std::filesystem::path staging_;  // streaming: where files go; empty otherwise
  std::filesystem::path stagedFor_;
  size_t streamed_ = 0;
};

}  // namespace mb
