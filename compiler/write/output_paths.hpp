// write: where a command may write (docs/cli.md "Outputs"). A command writes only where it
// was told, replaces only what it wrote itself, and never touches what it reads. These checks
// run before any work starts; PackageWriter repeats the directory check at commit time.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace mb {

// The marker every directory matbricks writes carries (a package, a bench result directory).
// Only a directory holding it, an empty directory or a missing one is ever replaced.
inline constexpr const char* kOutputMarkerName = ".matbricks-package";
// The marker's bytes for a directory of `kind` ("package", "bench").
std::string outputMarkerText(const std::string& kind);
// True if `dir` holds a marker matbricks wrote (any kind).
bool carriesOutputMarker(const std::filesystem::path& dir);

// Something a command reads or owns; an output may not be it, contain it, or lie inside it.
struct ProtectedPath {
  std::filesystem::path path;
  std::string what;  // "material", "#included file", "shader library", "cache directory", ...
};

// Throws DiagnosticError E-OUTPUT-OVERLAPS-INPUT (at the output's path) if `output` is,
// contains or lies inside an existing protected path. Identity is compared by device and
// inode along the resolved path, so symlinks, "..", hard links and bind mounts are seen
// through. A protected path that does not exist protects nothing.
void refuseOverlap(const std::filesystem::path& output, const std::string& outputWhat,
                   const std::vector<ProtectedPath>& inputs);

// A directory output (-o DIR): throws E-OUTPUT-NOT-PACKAGE naming DIR and a few of its entries
// unless DIR does not exist, is an empty directory, or carries the marker.
void checkOutputDirectory(const std::filesystem::path& dir);

// A single-file output (a LUT, a report, a depfile): throws E-OUTPUT-NOT-FILE if it exists and
// is not a regular file (a directory, a device such as /dev/null), E-IO if its directory does
// not exist.
void checkOutputFile(const std::filesystem::path& file);

// The path a single-file output is written to: an existing symlink is followed, so the file it
// points at is replaced, not the link.
std::filesystem::path resolvedOutputFile(const std::filesystem::path& file);

}  // namespace mb
