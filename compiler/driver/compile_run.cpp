#include "driver/compile_run.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "compile/remote_cache.hpp"
#include "compile/shader_cache.hpp"
#include "core/cpp_identifiers.hpp"
#include "core/package_stages.hpp"
#include "core/vocabulary.hpp"
#include "driver/command_inputs.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "write/depfile.hpp"
#include "write/package_contents.hpp"
#include "write/package_writer.hpp"
#include "write/shard_writer.hpp"

namespace mb {
namespace {

// Two materials of one name would write the same files: refuse rather than keep either.
void refuseDuplicateKeys(const std::vector<Permutation>& perms, const std::vector<const MaterialDesc*>& sources) {
  std::map<std::string, size_t> byKey;
  std::vector<Diagnostic> duplicates;
  for (size_t i = 0; i < perms.size(); ++i) {
    auto [it, fresh] = byKey.emplace(perms[i].key(), i);
    if (!fresh)
      duplicates.push_back({Severity::Error,
                            "E-DUPLICATE-MATERIAL",
                            {sources[i]->sourceFile, 1, 1},
                            "material '" + sources[i]->name + "' is also defined in " +
                                sources[it->second]->sourceFile + ": permutation '" + perms[i].key() +
                                "' would be written twice",
                            "rename one of them"});
  }
  if (!duplicates.empty()) throw DiagnosticError(duplicates);
}

// Before any compiling: -o must be new, empty or a package, and neither it nor the depfile may
// be, contain or lie inside what the compile reads or the cache (docs/cli.md "Outputs").
void refuseUnsafeOutputs(const CompileRequest& r, const ShaderLibrary& lib, const SceneDesc& scene,
                         const std::vector<MaterialDesc>& materials, const std::filesystem::path& cacheDir,
                         const std::vector<ProtectedPath>& more) {
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  inputs.insert(inputs.end(), more.begin(), more.end());
  std::vector<const MaterialDesc*> read;  // the files' materials, or the scene's
  for (const auto& m : materials) read.push_back(&m);
  for (const auto& m : scene.materials) read.push_back(&m.material);
  addMaterialInputs(inputs, read, r.scene);
  if (!cacheDir.empty()) inputs.push_back({cacheDir, "cache directory"});
  if (!r.out.empty()) checkDirectoryOutput(r.out, inputs);
  if (!r.depfile.empty()) {
    inputs.push_back({r.out, "output directory"});
    checkFileOutput(r.depfile, "depfile", inputs);
  }
}

std::unique_ptr<RemoteCache> openRemoteCache(const CompileRequest& r) {
  std::string url = r.cacheUrl;
  if (url.empty() && !r.noCache)
    if (const char* env = std::getenv("MATBRICKS_CACHE_URL"); env && *env) url = env;
  if (url.empty()) return nullptr;
  try {
    return std::make_unique<RemoteCache>(RemoteCacheOptions{url, r.cacheUrlLayout, r.cacheTimeout, r.cacheVerify});
  } catch (const DiagnosticError& e) {  // a bad option value: a usage error (exit 2)
    throw CompileUsageError((r.cacheUrl.empty() ? "MATBRICKS_CACHE_URL " : "--cache-url ") +
                            RemoteCache::redactUrl(url) + ": " + e.diagnostics().front().message);
  }
}

// What is refused before the library is read: usage errors (exit 2), then names (exit 3).
ShardSpec checkRequest(const CompileRequest& r) {
  if (r.scene.empty() == r.materials.empty())
    throw CompileUsageError("compile takes either MATERIAL files or --scene FILE, not both or neither");
  if (r.out.empty() && !r.explain) throw CompileUsageError("compile needs -o DIR (or --explain, which only counts)");
  if (!r.depfile.empty() && r.out.empty())
    throw CompileUsageError("--depfile needs -o DIR (its target is DIR/manifest.json)");
  if (r.noCache && !r.cacheUrl.empty())
    throw CompileUsageError("--cache-url conflicts with --no-cache (which turns every cache off)");
  if (std::string why = cppNamespaceRefusal(r.cppNamespace); !why.empty())
    throw DiagnosticError(
        {{Severity::Error, "E-INVALID-NAME", {"--namespace", 0, 0}, "'" + r.cppNamespace + "' " + why}});
  if (r.noCache && r.cacheVerify > 0)
    throw CompileUsageError("--cache-verify conflicts with --no-cache (there is no remote cache to verify)");
  // Bad input (exit 3), still before any work: a name option is a name, not a path.
  checkHeaderName(r.headerName, {"<command line>", 0, 0});
  ShardSpec shard;
  if (!r.shard.empty()) {
    std::string why;
    if (!parseShardSpec(r.shard, shard, why)) throw CompileUsageError(why);
    if (!r.depfile.empty())
      throw CompileUsageError("--depfile conflicts with --shard: a shard has no manifest.json (merge writes it)");
  }
  return shard;
}

}  // namespace

CompileOutcome runCompile(const CompileRequest& r, const CompileHooks& hooks, const ShardSet* mergeFrom,
                          const std::vector<ProtectedPath>& protectedInputs) {
  auto warn = [&](const std::vector<Diagnostic>& w) {
    if (!w.empty() && hooks.warnings) hooks.warnings(w);
  };
  CompileOutcome outcome;
  const ShardSpec shard = checkRequest(r);
  outcome.shard = shard;

  ShaderLibrary lib =
      ShaderLibrary::load(r.shaderlib.empty() ? ShaderLibrary::defaultRoot() : std::filesystem::path(r.shaderlib));
  SceneDesc scene;
  std::vector<MaterialDesc> materials;
  ScenePlan plan;
  std::vector<Target> targets = r.targets;
  if (!r.scene.empty()) {
    scene = loadScene(r.scene, lib);
    warn(scene.warnings);
    plan = planScene(scene, lib);
    if (targets.empty()) targets = scene.targets;
  } else {
    std::vector<Diagnostic> warnings;
    materials = loadMaterialFiles(r.materials, lib, warnings);
    warn(warnings);
    AxisPoint axes;
    axes.lights = canonicalLights(r.lights);
    axes.environment = r.environment;
    axes.precision = r.precision;
    axes.quality = r.quality;
    plan = planMaterials(materials, axes, lib);
    std::vector<const MaterialDesc*> sources;
    for (const auto& p : plan.required) sources.push_back(p.material);
    refuseDuplicateKeys(plan.required, sources);
  }
  if (targets.empty()) targets = {Target::Spirv};
  OptimizationLevel optimization = scene.optimization;  // O2 without a scene
  if (!r.optimization.empty() && !parseOptimizationLevel(r.optimization, optimization))
    throw CompileUsageError("-O: " + r.optimization + " is not a level");
  PackageStages stages;
  if (std::string why; !r.stages.empty() && !parsePackageStages(r.stages, stages, why))
    throw CompileUsageError("--stages: " + why);
  if (!stages.fragment && std::find(targets.begin(), targets.end(), Target::Webgl2) != targets.end())
    throw CompileUsageError(
        "--targets webgl2: WebGL 2.0 has no compute shaders, so webgl2 is built for the fragment stage only, which "
        "--stages leaves out");

  BuildOptions options;
  options.jobs = r.jobs;
  options.targets = targets;
  options.optimization = optimization;
  options.stages = stages;
  options.shard = shard;
  options.mergeFrom = mergeFrom;
  if (!mergeFrom)
    options.cacheDir = r.noCache ? std::filesystem::path()
                                 : (r.cacheDir.empty() ? ShaderCache::defaultDir() : std::filesystem::path(r.cacheDir));
  std::unique_ptr<RemoteCache> remote = mergeFrom ? nullptr : openRemoteCache(r);
  options.remote = remote.get();
  refuseUnsafeOutputs(r, lib, scene, materials, options.cacheDir, protectedInputs);
  // A path the depfile cannot carry is refused before anything is compiled or written.
  if (!r.depfile.empty()) checkDepfilePaths(depfileTarget(r.out), compileInputs(lib, plan.required, {}, {r.scene}));
  // Streamed: each window of permutations goes to the staged package (or shard) as soon as it
  // is built, so memory stays flat however large the scene (docs/targets.md "Memory").
  options.window = r.streamWindow;
  PackageInputs in;
  in.lib = &lib;
  in.plan = &plan;
  in.targets = targets;
  in.optimization = optimization;
  in.stages = stages;
  in.sceneFile = r.scene;
  in.headerName = r.headerName;
  in.cppNamespace = r.cppNamespace;
  PackageWriter writer(shard.whole() ? "package" : "shard");
  if (!r.out.empty()) writer.stage(r.out);
  std::unique_ptr<PackageStream> package;
  std::unique_ptr<ShardWriter> shardWriter;
  if (!r.out.empty() && shard.whole()) package = std::make_unique<PackageStream>(writer, in);
  if (!r.out.empty() && !shard.whole())
    shardWriter = std::make_unique<ShardWriter>(writer, shard, compileRequestJson(r));
  std::set<std::string> glslInputs;
  BuildStats& stats = outcome.stats;
  buildPermutationsStreaming(
      lib, plan.required, options,
      [&](size_t i, BuiltPermutation& b) {
        if (!b.inShard) return;
        if (hooks.built) hooks.built(b);
        if (package) package->add(plan.required[i], b);
        if (shardWriter) shardWriter->add(b.unit, b.artifacts, b.shader.key);
        if (!r.depfile.empty()) addGlslInputs(lib, b.shader.glsl, glslInputs);
      },
      &stats);
  warn(stats.cacheWarnings);
  if (r.explain && hooks.explain) {
    // Every required permutation was built; say how many glslang built now and how many the
    // cache or an identical emitted GLSL supplied.
    const size_t sharedGlsl = stats.permutations - stats.compiled - stats.cacheHits;
    std::string how = std::to_string(stats.compiled) + " built now, " + std::to_string(stats.cacheHits) +
                      " from the cache" +
                      (sharedGlsl ? ", " + std::to_string(sharedGlsl) + " sharing another's identical GLSL" : "");
    hooks.explain(explainText(plan, stats.permutations, stats.uniqueSpirv, how));
  }
  if (package) package->finish();
  if (shardWriter) shardWriter->finish(stats.planDigest, stats.units);
  if (!r.out.empty()) writer.commit(r.out);
  if (!r.depfile.empty()) {
    // After the package, so a failed compile leaves the previous depfile with its package.
    PackageWriter::writeFileAtomically(
        r.depfile, makeDepfile(depfileTarget(r.out), compileInputs(lib, plan.required, glslInputs, {r.scene})));
  }
  outcome.jobs = options.jobs;
  outcome.remote = remote != nullptr;
  return outcome;
}

}  // namespace mb
