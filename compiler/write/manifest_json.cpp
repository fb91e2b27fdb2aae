// write: manifest.json (docs/package.md "manifest.json"). nlohmann::json objects are
// std::map-ordered, so keys come out sorted and the bytes are stable.
#include <algorithm>

#include "compile/glsl_compiler.hpp"
#include "compile/reference_vertex.hpp"
#include "compile/targets.hpp"
#include "core/descriptor_bindings.hpp"
#include "emit/emitter.hpp"
#include "load/engine_data.hpp"
#include "write/package_parts.hpp"

namespace mb {
namespace {

nlohmann::json paramJson(const MaterialParam& p) {
  nlohmann::json j{{"name", p.name}, {"type", toString(p.type)}, {"constant", p.constant}, {"user", p.user}};
  j[p.constant ? "value" : "default"] = p.value;
  if (!p.constant) j["range"] = {p.range.lo, p.range.hi};
  return j;
}

nlohmann::json textureJson(const TextureBinding& t) {
  nlohmann::json j{{"parameter", t.parameterName()}, {"channels", t.channels}, {"srgb", t.srgb},
                   {"texture", t.texture},           {"image", t.image},       {"uri", t.uri},
                   {"texCoord", t.texCoord},         {"scale", t.scale}};
  if (t.transform)
    j["KHR_texture_transform"] = {{"offset", {t.offset[0], t.offset[1]}},
                                  {"rotation", t.rotation},
                                  {"scale", {t.uvScale[0], t.uvScale[1]}},
                                  {"texCoord", t.transformTexCoord >= 0 ? t.transformTexCoord : t.texCoord}};
  return j;
}

// The permutation's "engine" object (docs/gltf.md "Engine data").
nlohmann::json engineJson(const EngineData& e) {
  nlohmann::json textures = nlohmann::json::array();
  for (const auto& t : e.textures) textures.push_back(textureJson(t));
  nlohmann::json j{{"gltfMaterial", e.gltfMaterial},
                   {"alphaMode", e.alphaMode},
                   {"alphaCutoff", e.alphaCutoff},
                   {"doubleSided", e.doubleSided},
                   {"textures", textures}};
  if (e.anisotropyRotation) j["anisotropyRotation"] = *e.anisotropyRotation;
  return j;
}

nlohmann::json axesJson(const std::vector<AxisSize>& axes) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& a : axes) j[a.axis] = a.values;
  return j;
}

nlohmann::json permutationJson(const PackageInputs& in, const PackagedPermutation& p) {
  const Permutation& perm = *p.perm;
  const BuiltPermutation& b = *p.built;
  const MaterialDesc& m = *perm.material;
  nlohmann::json entry{{"key", b.shader.key},
                       {"material", m.name},
                       {"source", m.sourceFile},
                       {"model", m.model},
                       {"description", m.description},
                       {"features", m.features},
                       {"folded_features", perm.folded},
                       {"lights", lightTypeNames(perm.lights)},
                       {"environment", environmentModeName(perm.environment)},
                       {"precision", precisionName(perm.precision)},
                       {"quality", qualityName(perm.quality)},
                       {"light_methods", nlohmann::json::object()},
                       {"bricks", nlohmann::json::object()},
                       {"bricks_included", b.shader.bricks},
                       {"parameters", nlohmann::json::array()},
                       {"include", p.include},
                       {"includes", p.includes},
                       {"needs_fetch_hooks", needsFetchHooks(perm)},
                       {"record_layout", recordLayoutJson(b.shader.layout)}};
  // The kernel's module (docs/package.md "Stages": absent from a fragment-only package).
  if (!b.spirvHash.empty()) {
    entry["spirv_hash_xxh64"] = b.spirvHash;
    entry["spirv_instructions"] = b.spirvInstructions;
    entry["files"] = p.files;
    entry["reflection"] = b.artifacts.reflection.is_null() ? nlohmann::json::object() : b.artifacts.reflection;
  }
  for (LightType t : perm.lights)
    if (!m.lightMethod(t).empty()) entry["light_methods"][lightTypeName(t)] = m.lightMethod(t);
  for (const auto& [role, id] : boundRoles(*in.lib, perm)) entry["bricks"][role] = id;
  for (const auto& prm : m.params) entry["parameters"].push_back(paramJson(prm));
  if (m.engine) entry["engine"] = engineJson(*m.engine);
  if (!p.fragmentFiles.empty()) entry["fragment"] = fragmentEntryJson(p);
  return entry;
}

}  // namespace

nlohmann::json recordLayoutJson(const ProbeLayout& layout) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& in : layout.inputs)
    inputs.push_back({{"name", in.name}, {"type", toString(in.type)}, {"offset", in.offset}});
  return {{"unit", "float32"},
          {"inputs", std::move(inputs)},
          {"stride", layout.inStride},
          {"output", toString(layout.output)},
          {"output_stride", layout.outStride}};
}

ManifestWriter::ManifestWriter(const PackageInputs& in) : in_(in) {}

void ManifestWriter::add(const PackagedPermutation& p) {
  hashes_.insert(p.built->spirvHash.empty() ? p.built->fragmentHash : p.built->spirvHash);
  // The entry as dump(2) prints it two levels deep (an element of the top-level array).
  std::string text = permutationJson(in_, p).dump(2);
  std::string indented = count_ ? ",\n    " : "    ";
  for (char c : text) {
    indented += c;
    if (c == '\n') indented += "    ";
  }
  entries_.append(indented);
  ++count_;
}

void ManifestWriter::write(std::ostream& out) const {
  nlohmann::json targets = nlohmann::json::array();
  for (Target t : allTargets())
    if (t == Target::Spirv || std::find(in_.targets.begin(), in_.targets.end(), t) != in_.targets.end())
      targets.push_back(targetName(t));
  // The permutations are spliced in where this placeholder is printed: the document is what
  // nlohmann's dump(2) gives for the whole manifest, without holding it in memory.
  const std::string placeholder = "@@matbricks-permutations@@";
  nlohmann::json manifest{{"format", 1},
                          {"generator", "matbricks " MB_VERSION},
                          {"toolchain", toolchainVersion()},
                          {"header", in_.headerName},
                          {"namespace", in_.cppNamespace},
                          {"targets", std::move(targets)},
                          {"optimization", optimizationLevelName(in_.optimization)},
                          {"stages", packageStageNames(in_.stages)},
                          {"counts", {{"required", count_}, {"unique_spirv", hashes_.size()}}},
                          {"permutations", placeholder}};
  if (in_.stages.kernel)
    manifest["kernel"] = {{"records", {{"set", 0}, {"binding", kKernelInputBinding}}},
                          {"results", {{"set", 0}, {"binding", kKernelOutputBinding}}},
                          {"material_params", {{"set", 0}, {"binding", kKernelParamsBinding}, {"layout", "std140"}}},
                          {"push_constant", "uint count"}};
  if (in_.stages.fragment) {
    manifest["fragment"] = fragmentInterfaceJson();
    if (std::find(in_.targets.begin(), in_.targets.end(), Target::Webgl2) != in_.targets.end())
      manifest["fragment"]["webgl2"] = webgl2VertexJson(*in_.lib);
  }
  if (!in_.sceneFile.empty()) {
    manifest["scene"] = {{"file", in_.sceneFile},
                         {"possible", in_.plan->possible},
                         {"possible_axes", axesJson(in_.plan->possibleAxes)},
                         {"required_axes", axesJson(in_.plan->requiredAxes)}};
  }
  const std::string text = manifest.dump(2);
  const std::string quoted = "\"permutations\": \"" + placeholder + "\"";
  const size_t at = text.find(quoted);
  out << text.substr(0, at) << "\"permutations\": ";
  if (count_ == 0) {
    out << "[]";
  } else {
    out << "[\n";
    entries_.copyTo(out);
    out << "\n  ]";
  }
  out << text.substr(at + quoted.size()) << "\n";
}

}  // namespace mb
