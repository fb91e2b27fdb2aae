// matbricks compile MATERIAL... -o DIR: emit + compile every permutation, then write the
// package (one .glsl and one .spv per permutation, plus manifest.json) atomically.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "cli/cli_common.hpp"
#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "permute/permutation.hpp"
#include "write/package_writer.hpp"

namespace mb::cli {
namespace {

struct CompileArgs {
  std::vector<std::string> materials;
  std::string out;
  bool quiet = false;
  std::vector<std::string> lights{"dir"};
  std::string environment = "none";
  std::string precision = "fp32";
};

nlohmann::json paramJson(const MaterialParam& p) {
  nlohmann::json j{{"name", p.name}, {"type", toString(p.type)}, {"constant", p.constant}, {"user", p.user}};
  j[p.constant ? "value" : "default"] = p.value;
  if (!p.constant) j["range"] = {p.range.lo, p.range.hi};
  return j;
}

int runCompile(const CompileArgs& a, const GlobalOptions& g) {
  ShaderLibrary lib = loadLibrary(g);
  std::vector<MaterialDesc> materials = loadMaterials(a.materials, lib, g);
  std::vector<Permutation> perms = permutationsFor(materials);
  for (auto& perm : perms) {
    perm.lights = canonicalLights(a.lights);
    perm.environment = a.environment;
    perm.precision = a.precision;
  }

  // Two materials of one name would write the same files: refuse rather than keep either.
  std::map<std::string, const MaterialDesc*> byKey;
  std::vector<Diagnostic> duplicates;
  for (const auto& perm : perms) {
    auto [it, fresh] = byKey.emplace(perm.key(), perm.material);
    if (!fresh)
      duplicates.push_back({Severity::Error, "E-DUPLICATE-MATERIAL", {perm.material->sourceFile, 1, 1},
                            "material '" + perm.material->name + "' is also defined in " + it->second->sourceFile +
                                ": permutation '" + perm.key() + "' would be written twice",
                            "rename one of them"});
  }
  if (!duplicates.empty()) throw DiagnosticError(duplicates);

  PackageWriter pkg;
  nlohmann::json manifest{{"generator", "matbricks " MB_VERSION},
                          {"toolchain", toolchainVersion()},
                          {"permutations", nlohmann::json::array()}};
  std::vector<Diagnostic> errors;
  for (const auto& perm : perms) {
    EmittedShader shader = emitPermutation(lib, perm);
    auto t0 = std::chrono::steady_clock::now();
    CompileResult compiled;
    try {
      // fp16 skips spirv-opt, as validation does (probe_program.cpp: SPIRV-Tools v2023.1's
      // folding emits invalid 16-bit constants).
      CompileOptions options;
      options.optimize = perm.precision == "fp32";
      compiled = compileComputeGlsl(shader.glsl, shader.fileName, options);
    } catch (const DiagnosticError& e) {
      errors.insert(errors.end(), e.diagnostics().begin(), e.diagnostics().end());
      continue;
    }
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::string hash = contentHash(compiled.spirv.data(), compiled.spirv.size() * 4);
    pkg.addFile(shader.key + ".glsl", shader.glsl);
    pkg.addFile(shader.key + ".spv", compiled.spirv);

    const MaterialDesc& m = *perm.material;
    nlohmann::json entry{{"key", shader.key},
                         {"material", m.name},
                         {"source", m.sourceFile},
                         {"model", m.model},
                         {"description", m.description},
                         {"features", m.features},
                         {"lights", perm.lights},
                         {"environment", perm.environment},
                         {"precision", perm.precision},
                         {"glsl", shader.key + ".glsl"},
                         {"spirv", shader.key + ".spv"},
                         {"spirv_hash_xxh64", hash},
                         {"spirv_instructions", spirvInstructionCount(compiled.spirv)},
                         {"bricks", nlohmann::json::object()},
                         {"bricks_included", shader.bricks},
                         {"parameters", nlohmann::json::array()},
                         {"probe_inputs", shader.layout.columns()}};
    for (const auto& [role, id] : boundRoles(lib, perm)) entry["bricks"][role] = id;
    for (const auto& p : m.params) entry["parameters"].push_back(paramJson(p));
    manifest["permutations"].push_back(entry);
    if (!a.quiet) {
      std::printf("compiled %-44s %7.2f ms  %5zu instructions  %s\n", shader.key.c_str(), ms,
                  spirvInstructionCount(compiled.spirv), hash.c_str());
    }
  }
  if (!errors.empty()) throw DiagnosticError(errors);  // nothing written
  pkg.addFile("manifest.json", manifest.dump(2) + "\n");
  pkg.commit(a.out);
  if (!a.quiet) std::printf("wrote %zu permutation(s) to %s\n", perms.size(), a.out.c_str());
  return kExitOk;
}

}  // namespace

Command addCompileCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "Compile materials into a package of SPIR-V and GLSL");
  cmd->add_option("materials", args->materials, "Material files: .json, .mat (macro form), .gltf/.glb (one material each)")->required();
  cmd->add_option("-o,--output", args->out, "Package directory (replaced atomically)")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->add_option("--lights", args->lights, "Light types every permutation shades (default: dir)")
      ->delimiter(',')
      ->check(CLI::IsMember(allLightTypes()));
  cmd->add_option("--environment", args->environment, "Environment mode (default: none)")
      ->check(CLI::IsMember(allEnvironmentModes()));
  cmd->add_option("--precision", args->precision, "fp32 or fp16")->check(CLI::IsMember({"fp32", "fp16"}));
  return {cmd, [args, &g] { return runCompile(*args, g); }};
}

}  // namespace mb::cli
