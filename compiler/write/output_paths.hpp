// write: where a command may write (docs/cli.md "Outputs"). A command writes only where it
// was told, replaces only what it wrote itself, and never touches what it reads. These checks
// run before any work starts; PackageWriter repeats the directory check at commit time.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "write/output_marker.hpp"

namespace mb {

// Every directory matbricks writes carries a marker (write/output_marker.hpp) listing the
// files it wrote. Only a missing directory, an empty one, or one holding nothing but what its
// marker lists (same sizes and hashes, no mount point) is ever replaced.

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

// A directory output (-o DIR): throws unless DIR does not exist, is an empty directory, or
// holds nothing but what its marker lists: E-OUTPUT-NOT-PACKAGE (not a directory, or no
// marker; names a few entries), E-OUTPUT-MOUNT (a mount point inside: never removed across),
// E-OUTPUT-UNLISTED (files the marker does not list, or listed files since changed; names
// them). A symlink DIR is judged by the directory it points to.
void checkOutputDirectory(const std::filesystem::path& dir);

// The directory a directory output is written to: symlinks along the path and at its end are
// followed (also a dangling one: the package is created where it points), so `-o LINK`
// replaces the package LINK points to and the link stays.
std::filesystem::path resolvedOutputDirectory(const std::filesystem::path& dir);

// A name option that becomes one file name inside an output directory (compile --header): a
// usage error E-OUTPUT-NAME at `at` unless it is one plain name: not empty, no '/' or '\\',
// not "." or "..", no leading dot, no control character.
void checkOutputName(const std::string& name, const std::string& option, const SourceLocation& at);

// A single-file output (a LUT, a report, a depfile): throws E-OUTPUT-NOT-FILE if it exists and
// is not a regular file (a directory, a device such as /dev/null), E-IO if its directory does
// not exist.
void checkOutputFile(const std::filesystem::path& file);

// The path a single-file output is written to: an existing symlink is followed, so the file it
// points at is replaced, not the link.
std::filesystem::path resolvedOutputFile(const std::filesystem::path& file);

}  // namespace mb
