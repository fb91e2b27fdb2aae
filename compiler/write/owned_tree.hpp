// write: what a marked output directory holds against what its marker lists, and removing
// only what is matbricks' own. Both walk the tree with openat(2) and never follow a symlink
// nor enter another file system (a different st_dev, or a mount root by statx), so a bind
// mount or a symlink inside a package is never emptied through it.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "write/output_marker.hpp"

namespace mb {

// One thing in a directory that its marker does not account for.
struct ForeignEntry {
  std::string path;  // relative to the directory; directories end in '/'
  std::string why;   // "is a mount point", "not listed", "changed since matbricks wrote it", ...
  bool mountPoint = false;
};

// Everything under `dir` that `marker` does not list with the same size and content hash,
// mount points first. The marker itself and the directories leading to listed files are
// accounted for; a listed file that is gone is not a problem.
std::vector<ForeignEntry> foreignEntries(const std::filesystem::path& dir, const OutputMarker& marker);

// Removes under `dir` every file for which `owned(relativePath)` is true, then every directory
// left empty, then the marker, then `dir` itself: the marker goes last, so a run killed while
// removing leaves a directory the next run still recognises as ours. Never follows a symlink
// (one that is owned is removed as a link) and never enters another file system.
// `afterEach` runs after each removal (the crash test's fault point). True when `dir` is gone.
bool removeOwnedTree(const std::filesystem::path& dir, const std::function<bool(const std::string&)>& owned,
                     const std::function<void()>& afterEach = {});

}  // namespace mb
