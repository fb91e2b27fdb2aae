// core: the one way matbricks reads a file it was given or finds (materials, includes, glTF
// and its buffers, scenes, CSV, manifests, output markers, cache and shard entries). Only a
// regular file is read: a FIFO, a device, a socket or a directory is refused at once, before
// anything can block. The size limit of the input's kind is checked before reading, and the
// read itself never goes past it (a file that grows while read is refused, not followed).
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/diagnostics.hpp"

namespace mb {

// What an input is, for messages and for its size limit.
struct InputKind {
  const char* what;         // "material file", "CSV file", "cache entry", ...
  std::uintmax_t maxBytes;  // larger is certainly not one of these
};

// The limit of every kind of input in one place (docs/bad-inputs.md "Input files").
namespace input_kind {
inline constexpr InputKind kMaterial{"material JSON file", std::uintmax_t{16} << 20};
inline constexpr InputKind kMacroMaterial{"macro-form material file", std::uintmax_t{16} << 20};
inline constexpr InputKind kMacroInclude{"macro-form include file", std::uintmax_t{16} << 20};
inline constexpr InputKind kSurface{"GLSL surface file", std::uintmax_t{16} << 20};
inline constexpr InputKind kScene{"scene file", std::uintmax_t{16} << 20};
inline constexpr InputKind kGltf{"glTF file", std::uintmax_t{256} << 20};
// A .glb is never read whole: its header, its chunk headers and its JSON chunk (at most
// kGltf's limit) are read; a BIN chunk of images may be as large as it likes.
inline constexpr InputKind kGlb{"glTF binary (.glb) file", std::uintmax_t{1} << 40};
inline constexpr InputKind kGltfBuffer{"glTF buffer", std::uintmax_t{256} << 20};
inline constexpr InputKind kCsv{"CSV file", std::uintmax_t{1} << 40};  // streamed, never held whole
inline constexpr InputKind kJson{"JSON file", std::uintmax_t{256} << 20};
inline constexpr InputKind kManifest{"package manifest", std::uintmax_t{256} << 20};
// An output marker lists every file of its directory: 10^5 permutations make some 10 MB.
inline constexpr InputKind kMarker{"matbricks output marker", std::uintmax_t{256} << 20};
inline constexpr InputKind kCacheEntry{"cache entry", std::uintmax_t{64} << 20};
inline constexpr InputKind kShardFile{"shard file", std::uintmax_t{64} << 20};
inline constexpr InputKind kMarkdown{"Markdown file", std::uintmax_t{16} << 20};
inline constexpr InputKind kLibraryFile{"shader library file", std::uintmax_t{16} << 20};
}  // namespace input_kind

// Why a file could not be read: code E-FILE-NOT-FOUND (missing or unreadable),
// E-FILE-NOT-REGULAR (a directory, FIFO, device or socket) or E-FILE-TOO-LARGE.
struct InputFileError {
  std::string code;
  std::string message;  // names the path and the kind, e.g. "'x' is a FIFO: expected a CSV file"
};

// A regular file opened for reading, checked against its kind's limit. Move-only; closes on
// destruction. The descriptor was opened non-blocking (a FIFO without a writer does not hang
// the open) and is blocking again once the file is known to be regular.
class InputFile {
 public:
  // Opens `path` as an input of `kind`; on failure returns nothing and fills `error`.
  static std::optional<InputFile> open(const std::filesystem::path& path, const InputKind& kind, InputFileError& error);
  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&& other) noexcept;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  std::uintmax_t size() const { return size_; }  // at open
  // Up to `n` bytes into `buffer`; 0 at the end. Never reads past the kind's limit: reading
  // more than that fills `error` (E-FILE-TOO-LARGE) and returns -1, as does a read error (E-IO).
  long read(char* buffer, std::size_t n, InputFileError& error);
  // Up to `n` bytes at `offset` (which must lie within the kind's limit), without moving the
  // position `read` uses; fewer at the end of the file. -1 with `error` filled on a read error.
  long readAt(std::uintmax_t offset, char* buffer, std::size_t n, InputFileError& error);
  // The rest of the file (at most the kind's limit), or nothing with `error` filled.
  std::optional<std::string> readAll(InputFileError& error);

 private:
  InputFile(int fd, std::filesystem::path path, InputKind kind, std::uintmax_t size);
  int fd_ = -1;
  std::filesystem::path path_;
  InputKind kind_{};
  std::uintmax_t size_ = 0;
  std::uintmax_t consumed_ = 0;
};

// The whole file, or nothing with `error` filled.
std::optional<std::string> readInputFile(const std::filesystem::path& path, const InputKind& kind,
                                         InputFileError& error);
// The whole file; throws DiagnosticError with the error's code at `at` (at the file itself when
// `at` has no file).
std::string readInputFileOrThrow(const std::filesystem::path& path, const InputKind& kind,
                                 const SourceLocation& at = SourceLocation());

}  // namespace mb
