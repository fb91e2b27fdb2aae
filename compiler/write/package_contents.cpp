// INTERIM (replaced by the engine-ready package): the previous layout.
#include "write/package_contents.hpp"

#include <nlohmann/json.hpp>

#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"

namespace mb {
namespace {

nlohmann::json paramJson(const MaterialParam& p) {
  nlohmann::json j{{"name", p.name}, {"type", toString(p.type)}, {"constant", p.constant}, {"user", p.user}};
  j[p.constant ? "value" : "default"] = p.value;
  if (!p.constant) j["range"] = {p.range.lo, p.range.hi};
  return j;
}

}  // namespace

void addPackageFiles(PackageWriter& pkg, const PackageInputs& in) {
  nlohmann::json manifest{{"generator", "matbricks " MB_VERSION},
                          {"toolchain", toolchainVersion()},
                          {"permutations", nlohmann::json::array()}};
  for (size_t i = 0; i < in.built->size(); ++i) {
    const BuiltPermutation& b = (*in.built)[i];
    const Permutation& perm = in.plan->required[i];
    pkg.addFile(b.shader.key + ".glsl", b.shader.glsl);
    pkg.addFile(b.shader.key + ".spv", b.artifacts.spirv);
    const MaterialDesc& m = *perm.material;
    nlohmann::json entry{{"key", b.shader.key},
                         {"material", m.name},
                         {"source", m.sourceFile},
                         {"model", m.model},
                         {"description", m.description},
                         {"features", m.features},
                         {"lights", perm.lights},
                         {"environment", perm.environment},
                         {"precision", perm.precision},
                         {"glsl", b.shader.key + ".glsl"},
                         {"spirv", b.shader.key + ".spv"},
                         {"spirv_hash_xxh64", b.spirvHash},
                         {"spirv_instructions", spirvInstructionCount(b.artifacts.spirv)},
                         {"bricks", nlohmann::json::object()},
                         {"bricks_included", b.shader.bricks},
                         {"parameters", nlohmann::json::array()},
                         {"probe_inputs", b.shader.layout.columns()}};
    for (const auto& [role, id] : boundRoles(*in.lib, perm)) entry["bricks"][role] = id;
    for (const auto& p : m.params) entry["parameters"].push_back(paramJson(p));
    manifest["permutations"].push_back(entry);
  }
  pkg.addFile("manifest.json", manifest.dump(2) + "\n");
}

}  // namespace mb
