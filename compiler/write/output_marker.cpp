#include "write/output_marker.hpp"

#include <nlohmann/json.hpp>

#include "core/input_file.hpp"

namespace mb {
namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "matbricks-output";

// One line of the marker, or a discarded value when it is not JSON.
nlohmann::json parseLine(const std::string& text, size_t begin, size_t end) {
  return nlohmann::json::parse(text.begin() + static_cast<std::ptrdiff_t>(begin),
                               text.begin() + static_cast<std::ptrdiff_t>(end), nullptr, false);
}

bool isHeader(const nlohmann::json& j) {
  return j.is_object() && j.contains("format") && j["format"].is_string() && j["format"] == kFormat &&
         j.contains("version") && j["version"].is_number_integer();
}

}  // namespace

std::string outputMarkerHeader(const std::string& kind) {
  return nlohmann::json{{"format", kFormat}, {"version", 2}, {"kind", kind}, {"generator", "matbricks " MB_VERSION}}
             .dump() +
         "\n";
}

std::string outputMarkerLine(const std::string& path, const MarkedFile& file) {
  return nlohmann::json{{"path", path}, {"size", file.size}, {"xxh64", file.xxh64}}.dump() + "\n";
}

std::string outputMarkerEnd(std::uint64_t files) {
  return nlohmann::json{{"end", true}, {"files", files}}.dump() + "\n";
}

std::optional<OutputMarker> readOutputMarker(const fs::path& dir, std::string& why) {
  InputFileError error;
  const std::optional<std::string> text = readInputFile(dir / kOutputMarkerName, input_kind::kMarker, error);
  if (!text) {
    why = error.message;
    return std::nullopt;
  }
  OutputMarker m;
  size_t lineEnd = text->find('\n');
  const nlohmann::json header = parseLine(*text, 0, lineEnd == std::string::npos ? text->size() : lineEnd);
  if (!isHeader(header)) {
    // Version 1: one pretty-printed object, which lists no files.
    const nlohmann::json whole = nlohmann::json::parse(*text, nullptr, false);
    if (!isHeader(whole) || whole["version"] != 1) {
      why = "'" + (dir / kOutputMarkerName).string() + "' is not a matbricks output marker";
      return std::nullopt;
    }
    m.version = 1;
    m.kind = whole.value("kind", "");
    m.complete = true;
    return m;
  }
  m.version = header["version"].get<int>();
  m.kind = header.value("kind", "");
  // Lines after the header: files, then the end line. A line cut short by a kill, or anything
  // after the end line, leaves the marker incomplete: a staging directory, not a package.
  std::uint64_t listed = 0;
  for (size_t begin = lineEnd; begin != std::string::npos && begin + 1 < text->size(); begin = lineEnd) {
    lineEnd = text->find('\n', begin + 1);
    if (lineEnd == std::string::npos) return m;  // no newline: cut short
    const nlohmann::json line = parseLine(*text, begin + 1, lineEnd);
    if (m.complete || !line.is_object()) {
      m.complete = false;
      return m;
    }
    if (line.contains("end")) {
      m.complete = line.value("files", std::uint64_t{0}) == listed;
      continue;
    }
    const auto path = line.find("path"), size = line.find("size"), hash = line.find("xxh64");
    if (path == line.end() || !path->is_string() || size == line.end() || !size->is_number_unsigned() ||
        hash == line.end() || !hash->is_string())
      return m;
    m.files[path->get<std::string>()] = {size->get<std::uint64_t>(), hash->get<std::string>()};
    ++listed;
  }
  return m;
}

bool carriesOutputMarker(const fs::path& dir) {
  std::string why;
  return readOutputMarker(dir, why).has_value();
}

}  // namespace mb
