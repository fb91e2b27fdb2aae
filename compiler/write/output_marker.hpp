// write: the marker in every directory matbricks writes (docs/cli.md "Outputs"), and what it
// records: the directory's kind and every file the writer put there, with its size and hash,
// so a later run replaces exactly those files and refuses a directory holding anything else.
//
// Format (JSON lines, so it is appended to while a package streams and read without holding a
// document tree): a header object, one object per file, and an end object once the writer
// finished. A marker without its end line is a staging directory a killed run left.
//   {"format":"matbricks-output","generator":"matbricks 0.9","kind":"package","version":2}
//   {"path":"spirv/0123456789abcdef.spv","size":1234,"xxh64":"0123456789abcdef"}
//   {"end":true,"files":1}
// Version 1 (one pretty-printed object, no file list) is still read: see readOutputMarker.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

namespace mb {

inline constexpr const char* kOutputMarkerName = ".matbricks-package";

struct MarkedFile {
  std::uint64_t size = 0;
  std::string xxh64;  // contentHash of the bytes written
};

struct OutputMarker {
  int version = 0;
  std::string kind;
  bool complete = false;                    // version 2: the end line is there
  std::map<std::string, MarkedFile> files;  // version 2: relative path -> what was written
};

// The header line of a directory of `kind` ("package", "bench", "report", "preview", "shard").
std::string outputMarkerHeader(const std::string& kind);
// One file's line.
std::string outputMarkerLine(const std::string& path, const MarkedFile& file);
// The end line, after `files` file lines.
std::string outputMarkerEnd(std::uint64_t files);

// What a marker says; `why` is filled when it is missing or not one of ours (a FIFO, a file
// over the marker's size limit, unparseable text). Read with core/input_file.hpp's bounded
// reader: a FIFO or device never blocks, a huge file is never read.
std::optional<OutputMarker> readOutputMarker(const std::filesystem::path& dir, std::string& why);

// True if `dir` holds a marker matbricks wrote (any kind, any version, complete or not).
bool carriesOutputMarker(const std::filesystem::path& dir);

}  // namespace mb
