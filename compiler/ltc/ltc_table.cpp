#include "ltc/ltc_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/diagnostics.hpp"
#include "core/json_document.hpp"

namespace mb::ltc {
namespace {

constexpr const char* kFormat = "matbricks-ltc-table";
constexpr int kVersion = 1;
constexpr size_t kColumns = 6;  // m00, m02, m20, m22, norm, fresnel

// Nine significant digits print every fp32 value exactly (it reads back to the same float).
std::string number(float x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(x));
  return buf;
}

[[noreturn]] void fail(const JsonDocument& doc, const std::string& pointer, const std::string& message) {
  throw DiagnosticError({{Severity::Error, "E-LTC-TABLE", doc.valueAt(pointer), message, ""}});
}

}  // namespace

ref::ltc::Mat3 TableEntry::minv() const {
  return ref::ltc::Mat3{{{double(m00), 0.0, double(m02)}, {0.0, 1.0, 0.0}, {double(m20), 0.0, double(m22)}}};
}

TableSample sampleBilinear(const Table& t, double perceptualRoughness, double NoV) {
  const double last = t.size - 1.0;
  const double x = std::clamp(perceptualRoughness, 0.0, 1.0) * last;
  const double y = std::sqrt(std::clamp(1.0 - NoV, 0.0, 1.0)) * last;
  const uint32_t i0 = std::min(static_cast<uint32_t>(x), t.size - 2),
                 j0 = std::min(static_cast<uint32_t>(y), t.size - 2);
  const double fx = x - i0, fy = y - j0;
  double v[kColumns] = {};
  auto add = [&](uint32_t i, uint32_t j, double w) {
    const TableEntry& e = t.at(i, j);
    const float c[kColumns] = {e.m00, e.m02, e.m20, e.m22, e.norm, e.fresnel};
    for (size_t k = 0; k < kColumns; ++k) v[k] += w * c[k];
  };
  add(i0, j0, (1 - fx) * (1 - fy));
  add(i0, j0 + 1, (1 - fx) * fy);
  add(i0 + 1, j0, fx * (1 - fy));
  add(i0 + 1, j0 + 1, fx * fy);
  TableSample s;
  s.minv = ref::ltc::Mat3{{{v[0], 0.0, v[1]}, {0.0, 1.0, 0.0}, {v[2], 0.0, v[3]}}};
  s.norm = v[4];
  s.fresnel = v[5];
  return s;
}

std::vector<float> tableTexels(const Table& specular, const Table& sheen) {
  if (sheen.size != specular.size) throw std::invalid_argument("tableTexels: the LTC tables differ in size");
  std::vector<float> rgba;
  rgba.reserve(size_t{4} * specular.size * specular.size * 4);
  for (uint32_t i = 0; i < specular.size; ++i) {
    for (const Table* t : {&specular, &sheen}) {
      for (uint32_t j = 0; j < t->size; ++j) {
        const TableEntry& e = t->at(i, j);
        rgba.insert(rgba.end(), {e.m00, e.m02, e.m20, e.m22});
      }
      for (uint32_t j = 0; j < t->size; ++j) {
        const TableEntry& e = t->at(i, j);
        rgba.insert(rgba.end(), {e.norm, e.fresnel, 0.0f, 0.0f});
      }
    }
  }
  return rgba;
}

TableEntry toTableEntry(const LtcEntry& e) {
  return {static_cast<float>(e.minv[0][0]), static_cast<float>(e.minv[0][2]), static_cast<float>(e.minv[2][0]),
          static_cast<float>(e.minv[2][2]), static_cast<float>(e.norm),       static_cast<float>(e.fresnel)};
}

Table makeTable(uint32_t size, const FitSettings& settings, const std::vector<LtcEntry>& fitted) {
  Table t;
  t.size = size;
  t.settings = settings;
  for (const auto& e : fitted) t.entries.push_back(toTableEntry(e));
  return t;
}

std::string encodeTable(const Table& t, const std::string& command) {
  std::string s = "{\n";
  s += "  \"format\": \"" + std::string(kFormat) + "\",\n";
  s += "  \"version\": " + std::to_string(kVersion) + ",\n";
  s += "  \"command\": \"" + command + "\",\n";
  s += std::string("  \"lobe\": \"") +
       (t.settings.lobe == LobeKind::Charlie
            ? "Charlie D (alpha = max(r^2, 0.002025)) x Ashikhmin V x n.l; fresnel 0 (the sheen has none)"
            : "GGX D (alpha = max(r^2, 1e-4)) x height-correlated Smith V x n.l") +
       "\",\n";
  s += "  \"rows\": \"perceptual roughness r = i / (size - 1)\",\n";
  s += "  \"columns\": \"u = j / (size - 1), n.v = max(1 - u^2, 1e-4)\",\n";
  s += "  \"entry\": [\"minv00\", \"minv02\", \"minv20\", \"minv22\", \"norm\", \"fresnel\"],\n";
  s += "  \"size\": " + std::to_string(t.size) + ",\n";
  s += "  \"fit\": {\"lobe\": \"" + std::string(lobeName(t.settings.lobe)) +
       "\", \"samples\": " + std::to_string(t.settings.samples) +
       ", \"max_iterations\": " + std::to_string(t.settings.maxIterations) + "},\n";
  s += "  \"entries\": [\n";
  for (size_t k = 0; k < t.entries.size(); ++k) {
    const TableEntry& e = t.entries[k];
    s += "    [" + number(e.m00) + ", " + number(e.m02) + ", " + number(e.m20) + ", " + number(e.m22) + ", " +
         number(e.norm) + ", " + number(e.fresnel) + "]";
    s += k + 1 < t.entries.size() ? ",\n" : "\n";
  }
  s += "  ]\n}\n";
  return s;
}

Table loadTable(const std::string& path) {
  const JsonDocument doc = JsonDocument::load(path);
  const nlohmann::json& j = doc.root();
  if (!j.is_object() || !j.contains("format") || j["format"] != kFormat)
    fail(doc, "/format", "not an LTC table (\"format\" must be \"" + std::string(kFormat) + "\")");
  if (!j.contains("version") || j["version"] != kVersion)
    fail(doc, "/version", "unsupported LTC table version (this matbricks reads " + std::to_string(kVersion) + ")");
  if (!j.contains("size") || !j["size"].is_number_unsigned() || j["size"].get<uint64_t>() < 2 ||
      j["size"].get<uint64_t>() > 1024)
    fail(doc, "/size", "'size' must be an integer in [2, 1024]");
  Table t;
  t.size = j["size"].get<uint32_t>();
  if (j.contains("fit") && j["fit"].is_object()) {
    // Tables written before there was more than one lobe are GGX's.
    const nlohmann::json& fit = j["fit"];
    if (fit.contains("lobe") && !fit["lobe"].is_string()) fail(doc, "/fit/lobe", "'lobe' must be a string");
    const std::string lobe = fit.value("lobe", std::string("ggx"));
    if (lobe == "charlie")
      t.settings.lobe = LobeKind::Charlie;
    else if (lobe != "ggx")
      fail(doc, "/fit/lobe", "unknown LTC lobe '" + lobe + "' (this matbricks fits 'ggx' and 'charlie')");
    t.settings.samples = j["fit"].value("samples", t.settings.samples);
    t.settings.maxIterations = j["fit"].value("max_iterations", t.settings.maxIterations);
  }
  if (!j.contains("entries") || !j["entries"].is_array() || j["entries"].size() != size_t{t.size} * t.size)
    fail(doc, "/entries", "'entries' must hold size x size = " + std::to_string(size_t{t.size} * t.size) + " entries");
  for (size_t k = 0; k < j["entries"].size(); ++k) {
    const nlohmann::json& row = j["entries"][k];
    const std::string at = "/entries/" + std::to_string(k);
    if (!row.is_array() || row.size() != kColumns) fail(doc, at, "an entry must hold 6 numbers");
    float v[kColumns];
    for (size_t c = 0; c < kColumns; ++c) {
      if (!row[c].is_number() || !std::isfinite(row[c].get<double>()))
        fail(doc, at + "/" + std::to_string(c), "an entry's values must be finite numbers");
      v[c] = row[c].get<float>();
    }
    t.entries.push_back({v[0], v[1], v[2], v[3], v[4], v[5]});
  }
  return t;
}

}  // namespace mb::ltc
