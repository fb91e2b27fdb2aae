// glTF file level: asset version, extensionsUsed / extensionsRequired, material names, the
// texture records in each description, and resolving every material against the library.
#include "load/gltf_import.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "core/glsl_float.hpp"
#include "load/gltf_container.hpp"
#include "load/gltf_mapping.hpp"
#include "load/material_resolve.hpp"

namespace mb {

namespace {

using gltf::FileContext;

// asset.version "2.x" is required; asset.minVersion, when present, must not exceed 2.0
// (glTF 2.0 spec, "Asset": a loader rejects a minVersion it does not support).
void checkAsset(JsonFields& f) {
  if (!f.find("/asset")) {
    f.error("E-MISSING-FIELD", f.valueAt(""), "glTF is missing required field 'asset' (with \"version\": \"2.0\")");
    return;
  }
  if (!f.isObject("/asset")) return;
  auto version = f.string("/asset/version");
  if (!f.find("/asset/version")) {
    f.error("E-MISSING-FIELD", f.valueAt("/asset"), "asset is missing required field 'version' (expected \"2.0\")");
  } else if (version && version->rfind("2.", 0) != 0) {
    f.error("E-GLTF-VERSION", f.valueAt("/asset/version"),
            "glTF version '" + *version + "' is not supported: expected 2.x");
  }
  auto minVersion = f.string("/asset/minVersion");
  if (minVersion && *minVersion != "2.0")
    f.error("E-GLTF-VERSION", f.valueAt("/asset/minVersion"),
            "asset.minVersion '" + *minVersion + "' is not supported: expected 2.0");
}

size_t arraySize(JsonFields& f, const std::string& ptr) { return f.isArray(ptr) ? f.find(ptr)->size() : 0; }

std::string stemOf(const std::string& file) {
  std::string stem = gltf::identifierFrom(std::filesystem::path(file).stem().string());
  return stem.empty() ? "gltf" : stem;
}

// Unique identifiers: "Material.001" -> "Material_001"; unnamed -> "<stem>_material<i>";
// a clash gets "_2", "_3", ... in file order.
void assignNames(JsonFields& f, const FileContext& ctx, std::vector<GltfMaterial>& materials) {
  std::set<std::string> taken;
  for (auto& m : materials) {
    std::string base = gltf::identifierFrom(m.gltfName);
    if (base.empty()) base = ctx.stem + "_material" + std::to_string(m.index);
    std::string name = base;
    for (int k = 2; taken.count(name); ++k) name = base + "_" + std::to_string(k);
    taken.insert(name);
    std::string namePtr = JsonFields::member(JsonFields::element("/materials", m.index), "name");
    m.source.name = {name, f.find(namePtr) ? f.valueAt(namePtr) : m.source.model.where};
  }
}

std::string describeTexture(const TextureBinding& t) {
  std::string s = t.param.empty() ? t.parameterName() + " (applied by the engine to the shading normal"
                                  : t.param + " (" + t.channels + " of the texel";
  s += "): texture " + std::to_string(t.texture);
  if (t.image >= 0) s += ", image " + std::to_string(t.image);
  if (!t.uri.empty()) s += " '" + t.uri + "'";
  if (t.srgb) s += ", sRGB";
  s += ", TEXCOORD_" + std::to_string(t.texCoord);
  if (t.transform) s += ", KHR_texture_transform";
  if (t.scale != 1.0) s += ", scale " + glslFloat(t.scale, FloatDigits::Nine);
  return s;
}

// What the engine applies and the shader does not (docs/gltf.md "Engine data").
EngineData engineData(const GltfMaterial& m) {
  EngineData e;
  e.gltfMaterial = m.index;
  e.alphaMode = m.alphaMode;
  e.alphaCutoff = m.alphaCutoff;
  e.doubleSided = m.doubleSided;
  e.textures = m.textures;
  if (m.source.features.end() != std::find_if(m.source.features.begin(), m.source.features.end(),
                                              [](const SourceName& f) { return f.value == "anisotropy"; }))
    e.anisotropyRotation = m.anisotropyRotation;
  return e;
}

// The description carries what an engine needs to bind each texture input (docs/gltf.md).
void describe(GltfMaterial& m) {
  m.source.engine = engineData(m);
  std::string d = "glTF material " + std::to_string(m.index);
  if (!m.gltfName.empty()) d += " '" + m.gltfName + "'";
  d += " of " + m.source.file;
  if (!m.textures.empty()) {
    d += "; texture inputs: ";
    for (size_t i = 0; i < m.textures.size(); ++i) d += (i ? "; " : "") + describeTexture(m.textures[i]);
  }
  m.source.description = d;
}

}  // namespace

// A .glb's first buffer without a uri is its BIN chunk (glTF 2.0 spec, "GLB-stored Buffer"):
// the chunk may be up to 3 bytes longer (padding), never shorter. Materials never read it, so
// a short one is a warning for the engine, not an error (issue 18).
void checkBinChunk(JsonFields& f, const GltfContainerInfo& info, std::vector<Diagnostic>& warnings) {
  if (!info.glb || !f.isObject("/buffers/0") || f.find("/buffers/0/uri")) return;
  auto declared = f.number("/buffers/0/byteLength");
  if (!declared || *declared <= static_cast<double>(std::max<int64_t>(info.binChunkLength, 0))) return;
  std::string have = info.binChunkLength < 0 ? "the file has no BIN chunk"
                                             : "its BIN chunk holds " + std::to_string(info.binChunkLength);
  warnings.push_back({Severity::Warning, "W-GLB-BIN-SHORT", f.valueAt("/buffers/0/byteLength"),
                      "buffer 0 (the .glb's BIN chunk) declares " + std::to_string(static_cast<uint64_t>(*declared)) +
                          " bytes, but " + have +
                          " byte(s): the file is truncated or damaged, and an engine reading its meshes "
                          "or images will fail; materials do not read it"});
}

std::vector<GltfMaterial> mapGltfDocument(const JsonDocument& doc, const ShaderLibrary& lib,
                                          const GltfContainerInfo* container) {
  const GltfDefaults& defaults = lib.gltfDefaults();
  if (defaults.model.empty())
    throw DiagnosticError({{Severity::Error,
                            "E-GLTF-NO-DEFAULTS",
                            {(lib.root() / "manifest.json").string(), 1, 1},
                            "the shader library declares no 'gltf_defaults' (the model and bricks glTF "
                            "materials map to), so '" +
                                doc.file() + "' cannot be imported",
                            ""}});
  DiagnosticSink sink;
  JsonFields f(doc, sink);
  std::vector<GltfMaterial> materials;
  if (!f.isObject("")) throwInFileOrder(sink, doc.file());
  checkAsset(f);

  FileContext ctx(defaults);
  ctx.file = doc.file();
  ctx.stem = stemOf(doc.file());
  std::vector<std::string> used = f.strings("/extensionsUsed").value_or(std::vector<std::string>{});
  std::vector<std::string> required = f.strings("/extensionsRequired").value_or(std::vector<std::string>{});
  for (size_t i = 0; i < required.size(); ++i) {
    ctx.required.insert(required[i]);
    if (!gltf::isExtensionUnderstood(required[i]))
      f.error("E-GLTF-REQUIRED-EXTENSION", f.valueAt(JsonFields::element("/extensionsRequired", i)),
              "extension '" + required[i] +
                  "' is required by the file but not supported by matbricks "
                  "(supported: " +
                  quotedList(gltf::understoodExtensions()) + ")");
  }
  ctx.textureCount = arraySize(f, "/textures");
  ctx.imageCount = arraySize(f, "/images");

  std::set<std::string> usedByMaterials;
  size_t count = arraySize(f, "/materials");
  for (size_t i = 0; i < count; ++i) materials.push_back(gltf::mapMaterial(f, ctx, i, usedByMaterials));
  assignNames(f, ctx, materials);
  for (auto& m : materials) describe(m);

  // Listed but used by no material (geometry or texture extensions, for instance): one
  // warning for the file, carried by the first material.
  std::vector<Diagnostic> fileWarnings;
  if (container) checkBinChunk(f, *container, fileWarnings);
  for (size_t i = 0; i < used.size(); ++i) {
    const std::string& name = used[i];
    if (gltf::isExtensionUnderstood(name) || usedByMaterials.count(name) || ctx.required.count(name)) continue;
    fileWarnings.push_back(
        {Severity::Warning, "W-GLTF-UNSUPPORTED-EXTENSION", f.valueAt(JsonFields::element("/extensionsUsed", i)),
         "extension '" + name + "' is used by the file but not supported by matbricks: it is ignored"});
  }
  if (!materials.empty()) {
    auto& w = materials.front().source.warnings;
    w.insert(w.begin(), fileWarnings.begin(), fileWarnings.end());
  }

  if (sink.hasErrors()) {
    for (const auto& m : materials)
      for (const auto& w : m.source.warnings) sink.warning(w.code, w.where, w.message, w.suggestion);
    throwInFileOrder(sink, doc.file());
  }
  return materials;
}

std::vector<GltfMaterial> readGltf(const std::string& path, const ShaderLibrary& lib) {
  GltfContainerInfo info;
  JsonDocument doc = loadGltfMaterialJson(path, info);
  return mapGltfDocument(doc, lib, &info);
}

std::vector<GltfMaterial> parseGltf(const std::string& bytes, const std::string& file, const ShaderLibrary& lib) {
  GltfContainerInfo info;
  JsonDocument doc = parseGltfJson(bytes, file, info);
  return mapGltfDocument(doc, lib, &info);
}

std::vector<MaterialSource> readGltfMaterials(const std::string& path, const ShaderLibrary& lib) {
  std::vector<MaterialSource> out;
  for (auto& m : readGltf(path, lib)) out.push_back(std::move(m.source));
  return out;
}

std::vector<MaterialDesc> importGltfMaterials(const std::string& path, const ShaderLibrary& lib) {
  std::vector<MaterialSource> sources = readGltfMaterials(path, lib);
  DiagnosticSink sink;
  if (sources.empty())
    sink.error("E-GLTF-NO-MATERIALS", {path, 1, 1}, "the glTF file defines no materials: there is nothing to compile");
  std::vector<MaterialDesc> out;
  for (const auto& s : sources) out.push_back(resolveMaterialInto(s, lib, sink));
  if (sink.hasErrors()) {
    for (const auto& s : sources)
      for (const auto& w : s.warnings) sink.warning(w.code, w.where, w.message, w.suggestion);
  }
  throwInFileOrder(sink, path);
  return out;
}

}  // namespace mb
