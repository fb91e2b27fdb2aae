// .gltf / .glb reading (glTF 2.0 spec, "GLB File Format Specification"): little-endian
// uint32 header {magic "glTF", version 2, total length}, then chunks {length, type, data},
// each 4-byte aligned; the first chunk is JSON (0x4E4F534A), an optional second is BIN
// (0x004E4942), and chunks of other types are ignored. Nothing here trusts a length field
// before checking it against the bytes actually present.
#include "load/gltf_container.hpp"

#include "core/input_file.hpp"
#include "core/json_document.hpp"
#include "load/project_files.hpp"

#include <algorithm>
#include <climits>
#include <set>
#include <string_view>
#include <vector>
#include <cstdio>

namespace mb {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr size_t kHeaderSize = 12;
constexpr size_t kChunkHeaderSize = 8;
// JSON text is held in memory with its tree and a position per value (docs/formats.md "Input
// memory"); a .gltf with buffers embedded as data URIs is large but not this large.
constexpr uint64_t kMaxGltfJsonBytes = input_kind::kGltf.maxBytes;

// The bytes of a .glb, in memory or read on demand from the file: the BIN chunk can be
// hundreds of megabytes of images that material import never needs.
class ByteSource {
 public:
  virtual ~ByteSource() = default;
  virtual uint64_t size() const = 0;
  virtual std::string read(uint64_t offset, uint64_t count) = 0;  // within [0, size())

  uint32_t u32(uint64_t offset) {
    std::string b = read(offset, 4);
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[static_cast<size_t>(i)]);
    return v;
  }
};

class MemorySource : public ByteSource {
 public:
  explicit MemorySource(const std::string& bytes) : bytes_(bytes) {}
  uint64_t size() const override { return bytes_.size(); }
  std::string read(uint64_t offset, uint64_t count) override {
    return bytes_.substr(static_cast<size_t>(offset), static_cast<size_t>(count));
  }

 private:
  const std::string& bytes_;
};

// Reads through the one input reader (core/input_file.hpp), at offsets: the BIN chunk is
// never read.
class FileSource : public ByteSource {
 public:
  FileSource(InputFile& in, const std::string& path) : in_(in), path_(path) {}
  uint64_t size() const override { return in_.size(); }
  std::string read(uint64_t offset, uint64_t count) override {
    std::string out(static_cast<size_t>(count), '\0');
    InputFileError error;
    const long got = in_.readAt(offset, out.data(), out.size(), error);
    if (got < 0) throw DiagnosticError({{Severity::Error, error.code, {path_, 0, 0}, error.message}});
    // A file that shrank underneath us reads as zeros past its end: the structure checks
    // then fail on them.
    std::fill(out.begin() + got, out.end(), '\0');
    return out;
  }

 private:
  InputFile& in_;
  const std::string& path_;
};

void appendU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}

// A binary file has no lines: the position is line 1, column = byte offset + 1, and the
// message repeats the offset, which is what a hex dump shows (docs/gltf.md).
[[noreturn]] void glbError(const std::string& code, const std::string& file, uint64_t offset,
                           const std::string& message) {
  throw DiagnosticError({{Severity::Error,
                          code,
                          {file, 1, static_cast<int>(std::min<uint64_t>(offset + 1, INT32_MAX))},
                          "invalid .glb at byte " + std::to_string(offset) + ": " + message}});
}

bool isGlb(ByteSource& bytes) { return bytes.size() >= 4 && bytes.u32(0) == kGlbMagic; }

// A file named .glb is a GLB container whatever its bytes (a damaged header is a GLB error, not
// a JSON one); any other name is read as GLB when it starts with the magic, else as JSON text.
bool readsAsGlb(ByteSource& bytes, const std::string& file) { return lowerExtension(file) == ".glb" || isGlb(bytes); }

// A printable rendering of the 4 bytes where the magic should be, for the message.
std::string magicText(ByteSource& bytes) {
  std::string out;
  for (char c : bytes.read(0, 4)) {
    unsigned char u = static_cast<unsigned char>(c);
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", u);
    out += (u >= 0x20 && u < 0x7F) ? std::string(1, c) : std::string(hex);
  }
  return out;
}

// Which parts of a glTF's JSON a reader builds a tree of (loadGltf).
enum class GltfReader { kAll, kMaterials, kScene };

// Overwrites text[value, end) (one valid JSON value) with `0`, or with `{}` when `emptyObject`,
// and spaces, keeping its newlines: every other value keeps its line and column.
void blankValue(std::string& text, size_t value, size_t end, bool emptyObject) {
  for (size_t k = value; k < end; ++k)
    if (text[k] != '\n') text[k] = ' ';
  text[value] = emptyObject ? '{' : '0';
  if (emptyObject) text[end - 1] = '}';
}

// Whether a reader that reads the members named in `read` may read the member whose key is
// written `key`: a key with an escape may decode to one of them, so it is kept.
bool mayRead(const std::set<std::string>& read, const std::string& key) {
  return read.count(key) || key.find('\\') != std::string::npos;
}

// Calls member(key, value, end) for each member of the valid object whose '{' is at `open`
// (`member` may blank [value, end)); returns where the object's '}' is.
template <class Member>
size_t forEachMember(std::string& text, size_t open, Member&& member) {
  size_t i = skipJsonSpace(text, open + 1);
  while (i < text.size() && text[i] == '"') {
    const size_t keyEnd = skipJsonValue(text, i);
    const std::string key = text.substr(i + 1, keyEnd - i - 2);                 // as written: escapes not decoded
    const size_t value = skipJsonSpace(text, skipJsonSpace(text, keyEnd) + 1);  // past ':'
    const size_t end = skipJsonValue(text, value);
    member(key, value, end);
    i = skipJsonSpace(text, end);
    if (i < text.size() && text[i] == ',') i = skipJsonSpace(text, i + 1);
  }
  return i;
}

// The members of a node the scene walk reads (load/scene_gltf.cpp): a node array of millions
// of small objects (names, transforms) is most of a large scene's JSON, and a tree member costs
// ~100 bytes. A node with none of them becomes an empty object (still an object, so the walk
// says the same about it); the others keep them and blank the rest.
void blankUnreadNodeMembers(std::string& text, size_t array) {
  static const std::set<std::string> kRead = {"children", "extensions", "mesh"};
  size_t i = skipJsonSpace(text, array + 1);
  while (i < text.size() && text[i] != ']') {
    const size_t end = skipJsonValue(text, i);
    if (text[i] == '{') {
      std::vector<std::pair<size_t, size_t>> unread;
      bool readsAny = false;
      forEachMember(text, i, [&](const std::string& key, size_t value, size_t valueEnd) {
        if (mayRead(kRead, key))
          readsAny = true;
        else
          unread.push_back({value, valueEnd});
      });
      if (!readsAny) blankValue(text, i, end, true);
      for (size_t k = 0; readsAny && k < unread.size(); ++k) blankValue(text, unread[k].first, unread[k].second, false);
    }
    i = skipJsonSpace(text, end);
    if (i < text.size() && text[i] == ',') i = skipJsonSpace(text, i + 1);
  }
}

// Blanks the value of every top-level member that `reader` does not read (and, for a scene,
// the node members it does not read), so that they never enter the tree. Only valid JSON is
// touched (nlohmann's accept builds no tree); invalid JSON is left for the parse to report
// where it is wrong.
void blankUnreadMembers(std::string& text, GltfReader reader) {
  static const std::set<std::string> kMaterialReads = {"asset",          "buffers", "extensions", "extensionsRequired",
                                                       "extensionsUsed", "images",  "materials",  "samplers",
                                                       "textures"};
  static const std::set<std::string> kSceneReads = {"meshes", "nodes", "scene", "scenes"};
  if (reader == GltfReader::kAll || !nlohmann::json::accept(text)) return;
  const size_t i = skipJsonSpace(text, 0);
  if (i >= text.size() || text[i] != '{') return;
  forEachMember(text, i, [&](const std::string& key, size_t value, size_t end) {
    const bool scene = reader == GltfReader::kScene && mayRead(kSceneReads, key);
    if (!scene && !mayRead(kMaterialReads, key))
      blankValue(text, value, end, false);
    else if (scene && key == "nodes" && text[value] == '[')
      blankUnreadNodeMembers(text, value);
  });
}

std::string jsonChunkOf(ByteSource& bytes, const std::string& file, GltfContainerInfo& info) {
  info.glb = true;
  const uint64_t size = bytes.size();
  if (size < kHeaderSize)
    glbError("E-GLB-TRUNCATED", file, size, "the header needs 12 bytes, the file has " + std::to_string(size));
  if (bytes.u32(0) != kGlbMagic)
    glbError("E-GLB-HEADER", file, 0, "the magic is '" + magicText(bytes) + "', expected 'glTF'");
  uint32_t version = bytes.u32(4);
  if (version != 2)
    glbError("E-GLB-HEADER", file, 4, "container version " + std::to_string(version) + ", expected 2 (glTF 2.0)");
  uint64_t length = bytes.u32(8);
  if (length > size)
    glbError(
        "E-GLB-TRUNCATED", file, size,
        "the header says " + std::to_string(length) + " bytes, the file has " + std::to_string(size) + " (truncated)");
  if (length < size)
    glbError("E-GLB-HEADER", file, 8,
             "the header says " + std::to_string(length) + " bytes, the file has " + std::to_string(size));

  std::string json;
  size_t chunkIndex = 0;
  for (uint64_t at = kHeaderSize; at < length; ++chunkIndex) {
    if (length - at < kChunkHeaderSize)
      glbError("E-GLB-TRUNCATED", file, at, "chunk header needs 8 bytes, " + std::to_string(length - at) + " remain");
    uint64_t chunkLength = bytes.u32(at);
    uint32_t type = bytes.u32(at + 4);
    uint64_t data = at + kChunkHeaderSize;
    if (chunkLength > length - data)
      glbError("E-GLB-CHUNK", file, at,
               "chunk " + std::to_string(chunkIndex) + " says " + std::to_string(chunkLength) + " bytes, only " +
                   std::to_string(length - data) + " remain");
    if (chunkLength % 4 != 0)
      glbError("E-GLB-CHUNK", file, at,
               "chunk " + std::to_string(chunkIndex) + " length " + std::to_string(chunkLength) +
                   " is not a multiple of 4 (chunks are 4-byte aligned)");
    if (chunkIndex == 0) {
      if (type != kChunkJson) glbError("E-GLB-CHUNK", file, at + 4, "the first chunk must be of type JSON");
      if (chunkLength > kMaxGltfJsonBytes)
        glbError("E-FILE-TOO-LARGE", file, at,
                 "a JSON chunk of " + std::to_string(chunkLength) + " bytes is over the limit of " +
                     std::to_string(kMaxGltfJsonBytes));
      json = bytes.read(data, chunkLength);
    } else if (type == kChunkJson) {
      glbError("E-GLB-CHUNK", file, at + 4, "a second JSON chunk (only the first may be JSON)");
    } else if (type == kChunkBin && chunkIndex != 1) {
      glbError("E-GLB-CHUNK", file, at + 4, "a BIN chunk must directly follow the JSON chunk");
    } else if (type == kChunkBin) {
      info.binChunkLength = static_cast<int64_t>(chunkLength);
    }
    at = data + chunkLength;
  }
  if (chunkIndex == 0) glbError("E-GLB-TRUNCATED", file, kHeaderSize, "no JSON chunk");
  return json;
}

}  // namespace

JsonDocument parseGltfJson(const std::string& bytes, const std::string& file, GltfContainerInfo& info) {
  MemorySource source(bytes);
  // Positions of a .glb's JSON errors are line:column in the JSON chunk's text.
  return JsonDocument::parse(readsAsGlb(source, file) ? jsonChunkOf(source, file, info) : bytes, file);
}

JsonDocument parseGltfJson(const std::string& bytes, const std::string& file) {
  GltfContainerInfo info;
  return parseGltfJson(bytes, file, info);
}

namespace {

JsonDocument loadGltf(const std::string& path, GltfContainerInfo& info, GltfReader reader) {
  // Opened with the .glb container's limit (only its JSON chunk is ever read); JSON text is
  // held to kGltf's.
  InputFileError error;
  std::optional<InputFile> in = InputFile::open(path, input_kind::kGlb, error);
  if (!in) throw DiagnosticError({{Severity::Error, error.code, {path, 0, 0}, error.message}});
  FileSource source(*in, path);
  auto parse = [&](std::string text) {
    blankUnreadMembers(text, reader);
    return JsonDocument::parse(std::move(text), path);
  };
  if (readsAsGlb(source, path)) return parse(jsonChunkOf(source, path, info));
  const uint64_t size = in->size();
  if (size > kMaxGltfJsonBytes) {
    throw DiagnosticError({{Severity::Error,
                            "E-FILE-TOO-LARGE",
                            {path, 0, 0},
                            "a .gltf of " + std::to_string(size) + " bytes is over the limit of " +
                                std::to_string(kMaxGltfJsonBytes) + " bytes of JSON",
                            ""}});
  }
  return parse(source.read(0, size));
}

}  // namespace

JsonDocument loadGltfJson(const std::string& path, GltfContainerInfo& info) {
  return loadGltf(path, info, GltfReader::kAll);
}

JsonDocument loadGltfMaterialJson(const std::string& path, GltfContainerInfo& info) {
  return loadGltf(path, info, GltfReader::kMaterials);
}

JsonDocument loadGltfSceneJson(const std::string& path, GltfContainerInfo& info) {
  return loadGltf(path, info, GltfReader::kScene);
}

JsonDocument loadGltfJson(const std::string& path) {
  GltfContainerInfo info;
  return loadGltfJson(path, info);
}

std::string packGlb(const std::string& json, const std::string& bin) {
  std::string jsonChunk = json;
  while (jsonChunk.size() % 4 != 0) jsonChunk += ' ';
  std::string binChunk = bin;
  while (binChunk.size() % 4 != 0) binChunk += '\0';
  size_t total =
      kHeaderSize + kChunkHeaderSize + jsonChunk.size() + (bin.empty() ? 0 : kChunkHeaderSize + binChunk.size());
  std::string out;
  appendU32(out, kGlbMagic);
  appendU32(out, 2);
  appendU32(out, static_cast<uint32_t>(total));
  appendU32(out, static_cast<uint32_t>(jsonChunk.size()));
  appendU32(out, kChunkJson);
  out += jsonChunk;
  if (!bin.empty()) {
    appendU32(out, static_cast<uint32_t>(binChunk.size()));
    appendU32(out, kChunkBin);
    out += binChunk;
  }
  return out;
}

}  // namespace mb
