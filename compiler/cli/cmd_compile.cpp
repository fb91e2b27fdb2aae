// matbricks compile: materials (or a scene) -> the required permutations -> built in
// parallel through the cache, to every target -> a package written atomically
// (docs/cli.md, docs/scenes.md, docs/targets.md, docs/package.md).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <set>
#include <thread>

#include "cli/cli_common.hpp"
#include "cli/compile_run.hpp"
#include "compile/build.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "core/cpp_identifiers.hpp"
#include "core/json_fields.hpp"
#include "core/package_stages.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"
#include "write/depfile.hpp"
#include "write/package_contents.hpp"
#include "write/package_writer.hpp"
#include "write/shard_writer.hpp"

namespace mb::cli {
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
void refuseUnsafeOutputs(const CompileArgs& a, const ShaderLibrary& lib, const SceneDesc& scene,
                         const std::vector<MaterialDesc>& materials, const std::filesystem::path& cacheDir,
                         const std::vector<ProtectedPath>& more) {
  std::vector<ProtectedPath> inputs = libraryInputs(lib);
  inputs.insert(inputs.end(), more.begin(), more.end());
  std::vector<const MaterialDesc*> read;  // the files' materials, or the scene's
  for (const auto& m : materials) read.push_back(&m);
  for (const auto& m : scene.materials) read.push_back(&m.material);
  addMaterialInputs(inputs, read, a.scene);
  if (!cacheDir.empty()) inputs.push_back({cacheDir, "cache directory"});
  if (!a.out.empty()) checkDirectoryOutput(a.out, inputs);
  if (!a.depfile.empty()) {
    inputs.push_back({a.out, "output directory"});
    checkFileOutput(a.depfile, "depfile", inputs);
  }
}

// --header names one file at the package's top level (docs/package.md): a plain name, and not
// one the package itself writes there, which it would overwrite or collide with.
void checkHeaderName(const std::string& name, const SourceLocation& at) {
  checkOutputName(name, "--header", at);
  std::vector<std::string> taken{"manifest.json", "include", "fragment"};
  for (const auto& t : allTargetNames()) taken.push_back(t);
  if (std::find(taken.begin(), taken.end(), name) != taken.end())
    throw DiagnosticError({{Severity::Error, "E-OUTPUT-NAME", at,
                            "--header '" + name + "' is a name the package itself writes at its top level",
                            "give another file name such as materials.hpp"}});
}

std::unique_ptr<RemoteCache> openRemoteCache(const CompileArgs& a) {
  std::string url = a.cacheUrl;
  if (url.empty() && !a.noCache)
    if (const char* env = std::getenv("MATBRICKS_CACHE_URL"); env && *env) url = env;
  if (url.empty()) return nullptr;
  try {
    return std::make_unique<RemoteCache>(RemoteCacheOptions{url, a.cacheUrlLayout, a.cacheTimeout, a.cacheVerify});
  } catch (const DiagnosticError& e) {  // a bad option value: a usage error (exit 2)
    throw CLI::ValidationError((a.cacheUrl.empty() ? "MATBRICKS_CACHE_URL " : "--cache-url ") +
                               RemoteCache::redactUrl(url) + ": " + e.diagnostics().front().message);
  }
}

std::string remoteSummary(const BuildStats& s, const RemoteCache* remote) {
  if (!remote) return "";
  std::string text = ", " + std::to_string(s.remoteHits) + " of them from the remote cache, " +
                     std::to_string(s.remoteUploads) + " uploaded";
  if (s.remoteCorrupt) text += ", " + std::to_string(s.remoteCorrupt) + " corrupt remote blob(s) ignored";
  if (s.remoteMismatch) text += ", " + std::to_string(s.remoteMismatch) + " remote blob(s) of another unit ignored";
  if (s.remoteVerified) text += ", " + std::to_string(s.remoteVerified) + " verified by compiling again";
  return text;
}

}  // namespace

nlohmann::json compileCommandJson(const CompileArgs& a, const GlobalOptions& g) {
  return {{"materials", a.materials},       {"scene", a.scene},         {"lights", a.lights},
          {"environment", a.environment},   {"precision", a.precision}, {"quality", a.quality},
          {"targets", a.targets},           {"header", a.headerName},   {"namespace", a.cppNamespace},
          {"optimization", a.optimization}, {"stages", a.stages},       {"shaderlib", g.shaderlib}};
}

void compileArgsFromJson(const nlohmann::json& c, const std::string& file, CompileArgs& a, GlobalOptions& g) {
  auto notReadable = [&](const std::string& why) {
    return DiagnosticError({{Severity::Error,
                             "E-SHARD-NOT-SHARD",
                             {file, 0, 0},
                             "shard.json's 'command' is not readable: " + why,
                             "compile the shards again with this matbricks"}});
  };
  try {
    a.materials = c.at("materials").get<std::vector<std::string>>();
    a.scene = c.at("scene").get<std::string>();
    a.lights = c.at("lights").get<std::vector<std::string>>();
    a.environment = c.at("environment").get<std::string>();
    a.precision = c.at("precision").get<std::string>();
    a.quality = c.at("quality").get<std::string>();
    a.targets = c.at("targets").get<std::vector<std::string>>();
    a.optimization = c.at("optimization").get<std::string>();
    a.stages = c.at("stages").get<std::string>();
    a.headerName = c.at("header").get<std::string>();
    a.cppNamespace = c.at("namespace").get<std::string>();
    g.shaderlib = c.at("shaderlib").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw notReadable(e.what());
  }
  // What the command line's CLI11 checks would have refused.
  OptimizationLevel level;
  if (!a.optimization.empty() && !parseOptimizationLevel(a.optimization, level))
    throw notReadable("'optimization' is not a level: '" + a.optimization + "'");
  PackageStages stages;
  if (std::string why; !a.stages.empty() && !parsePackageStages(a.stages, stages, why))
    throw notReadable("'stages': " + why);
  for (const auto& t : a.targets)
    if (!parseTarget(t)) throw notReadable("'targets': '" + t + "' is not a target");
  // An axis value the emitter (precision), the quality selection (quality) or the validity
  // rules (environment) refused before the axes were types: the same code, now where the
  // shard is read.
  auto unknownAxisValue = [&](const std::string& code, const std::string& what, const std::string& value,
                              const std::vector<std::string>& names) {
    return DiagnosticError(
        {{Severity::Error, code, {file, 0, 0}, "unknown " + what + " '" + value + "'", "one of " + quotedList(names)}});
  };
  if (!parseEnvironmentMode(a.environment))
    throw unknownAxisValue("E-PERMUTATION-INVALID", "environment mode", a.environment, allEnvironmentModeNames());
  if (!parsePrecision(a.precision))
    throw unknownAxisValue("E-PRECISION", "precision", a.precision, allPrecisionNames());
  if (!parseQuality(a.quality))
    throw unknownAxisValue("E-PERMUTATION-INVALID", "quality level", a.quality, allQualityNames());
  checkHeaderName(a.headerName, {file, 0, 0});
}

int runCompile(const CompileArgs& a, const GlobalOptions& g, const ShardSet* mergeFrom,
               const std::vector<ProtectedPath>& protectedInputs) {
  // Usage errors exit 2 (CLI::ValidationError), as CLI11's own do.
  if (a.scene.empty() == a.materials.empty())
    throw CLI::ValidationError("compile takes either MATERIAL files or --scene FILE, not both or neither");
  if (!a.scene.empty())
    for (const CLI::Option* o : a.axisOptions)
      if (o && o->count() > 0)
        throw CLI::ValidationError(o->get_name() +
                                   " conflicts with --scene: the scene file sets that axis (docs/scenes.md)");
  if (a.out.empty() && !a.explain) throw CLI::ValidationError("compile needs -o DIR (or --explain, which only counts)");
  if (!a.depfile.empty() && a.out.empty())
    throw CLI::ValidationError("--depfile needs -o DIR (its target is DIR/manifest.json)");
  if (a.noCache && !a.cacheUrl.empty())
    throw CLI::ValidationError("--cache-url conflicts with --no-cache (which turns every cache off)");
  if (std::string why = cppNamespaceRefusal(a.cppNamespace); !why.empty())
    throw DiagnosticError(
        {{Severity::Error, "E-INVALID-NAME", {"--namespace", 0, 0}, "'" + a.cppNamespace + "' " + why}});
  if (a.noCache && a.cacheVerify > 0)
    throw CLI::ValidationError("--cache-verify conflicts with --no-cache (there is no remote cache to verify)");
  // Bad input (exit 3), still before any work: a name option is a name, not a path.
  checkHeaderName(a.headerName, {"<command line>", 0, 0});
  ShardSpec shard;
  if (!a.shard.empty()) {
    std::string why;
    if (!parseShardSpec(a.shard, shard, why)) throw CLI::ValidationError(why);
    if (!a.depfile.empty())
      throw CLI::ValidationError("--depfile conflicts with --shard: a shard has no manifest.json (merge writes it)");
  }

  ShaderLibrary lib = loadLibrary(g);
  SceneDesc scene;
  std::vector<MaterialDesc> materials;
  ScenePlan plan;
  std::vector<Target> targets = parseTargets(a.targets);  // checked by CLI11 or compileArgsFromJson
  if (!a.scene.empty()) {
    scene = loadScene(a.scene, lib);
    if (!scene.warnings.empty()) printDiagnostics(scene.warnings, g);
    plan = planScene(scene, lib);
    if (targets.empty()) targets = scene.targets;
  } else {
    materials = loadMaterials(a.materials, lib, g);
    AxisPoint axes;
    axes.lights = canonicalLights(a.lights);
    axes.environment = *parseEnvironmentMode(a.environment);  // checked by CLI11 or compileArgsFromJson
    axes.precision = *parsePrecision(a.precision);            // checked by CLI11 or compileArgsFromJson
    axes.quality = *parseQuality(a.quality);                  // checked by CLI11 or compileArgsFromJson
    plan = planMaterials(materials, axes, lib);
    std::vector<const MaterialDesc*> sources;
    for (const auto& p : plan.required) sources.push_back(p.material);
    refuseDuplicateKeys(plan.required, sources);
  }
  if (targets.empty()) targets = {Target::Spirv};
  OptimizationLevel optimization = scene.optimization;                                // O2 without a scene
  if (!a.optimization.empty()) parseOptimizationLevel(a.optimization, optimization);  // checked by CLI11
  PackageStages stages;  // checked by CLI11, or by compileArgsFromJson for a shard.json's
  if (std::string why; !a.stages.empty() && !parsePackageStages(a.stages, stages, why))
    throw CLI::ValidationError("--stages: " + why);

  BuildOptions options;
  options.jobs = a.jobs;
  options.targets = targets;
  options.optimization = optimization;
  options.stages = stages;
  options.shard = shard;
  options.mergeFrom = mergeFrom;
  if (!mergeFrom)
    options.cacheDir = a.noCache ? std::filesystem::path()
                                 : (a.cacheDir.empty() ? ShaderCache::defaultDir() : std::filesystem::path(a.cacheDir));
  std::unique_ptr<RemoteCache> remote = mergeFrom ? nullptr : openRemoteCache(a);
  options.remote = remote.get();
  refuseUnsafeOutputs(a, lib, scene, materials, options.cacheDir, protectedInputs);
  // A path the depfile cannot carry is refused before anything is compiled or written.
  if (!a.depfile.empty()) checkDepfilePaths(depfileTarget(a.out), compileInputs(lib, plan.required, {}, {a.scene}));
  // Streamed: each window of permutations goes to the staged package (or shard) as soon as it
  // is built, so memory stays flat however large the scene (docs/targets.md "Memory").
  options.window = a.streamWindow;
  PackageInputs in;
  in.lib = &lib;
  in.plan = &plan;
  in.targets = targets;
  in.optimization = optimization;
  in.stages = stages;
  in.sceneFile = a.scene;
  in.headerName = a.headerName;
  in.cppNamespace = a.cppNamespace;
  PackageWriter writer(shard.whole() ? "package" : "shard");
  if (!a.out.empty()) writer.stage(a.out);
  std::unique_ptr<PackageStream> package;
  std::unique_ptr<ShardWriter> shardWriter;
  if (!a.out.empty() && shard.whole()) package = std::make_unique<PackageStream>(writer, in);
  if (!a.out.empty() && !shard.whole())
    shardWriter = std::make_unique<ShardWriter>(writer, shard, compileCommandJson(a, g));
  std::set<std::string> glslInputs;
  BuildStats stats;
  buildPermutationsStreaming(
      lib, plan.required, options,
      [&](size_t i, BuiltPermutation& b) {
        if (!b.inShard) return;
        if (!a.quiet && !a.explain) {
          // The kernel's module, else (fragment only) the fragment shader's.
          const bool kernel = !b.spirvHash.empty();
          std::printf("compiled %-52s %7.2f ms  %5zu instructions  %s%s\n", b.shader.key.c_str(), b.compileMs,
                      kernel ? b.spirvInstructions : b.fragmentInstructions,
                      (kernel ? b.spirvHash : b.fragmentHash).c_str(),
                      b.fromCache ? (mergeFrom ? "  (from its shard)" : "  (cached)") : "");
        }
        if (package) package->add(plan.required[i], b);
        if (shardWriter) shardWriter->add(b.unit, b.artifacts, b.shader.key);
        if (!a.depfile.empty()) addGlslInputs(lib, b.shader.glsl, glslInputs);
      },
      &stats);
  if (!stats.cacheWarnings.empty()) printDiagnostics(stats.cacheWarnings, g);
  if (a.explain) {
    // Every required permutation was built; say how many glslang built now and how many the
    // cache or an identical emitted GLSL supplied.
    const size_t sharedGlsl = stats.permutations - stats.compiled - stats.cacheHits;
    std::string how = std::to_string(stats.compiled) + " built now, " + std::to_string(stats.cacheHits) +
                      " from the cache" +
                      (sharedGlsl ? ", " + std::to_string(sharedGlsl) + " sharing another's identical GLSL" : "");
    std::fputs(explainText(plan, stats.permutations, stats.uniqueSpirv, how).c_str(), stdout);
  }
  if (package) package->finish();
  if (shardWriter) shardWriter->finish(stats.planDigest, stats.units);
  if (!a.out.empty()) writer.commit(a.out);
  if (!a.depfile.empty()) {
    // After the package, so a failed compile leaves the previous depfile with its package.
    PackageWriter::writeFileAtomically(
        a.depfile, makeDepfile(depfileTarget(a.out), compileInputs(lib, plan.required, glslInputs, {a.scene})));
  }
  if (!a.quiet) {
    std::string what = std::to_string(stats.permutations) + " permutation(s)";
    if (!shard.whole())
      what = "shard " + shard.text() + ": " + std::to_string(stats.shardUnits) + " of " + std::to_string(stats.units) +
             " compile unit(s) of " + what;
    std::string how = std::to_string(stats.compiled) + " compiled, " + std::to_string(stats.cacheHits) + " cached";
    if (mergeFrom) how = "merged from " + std::to_string(mergeFrom->count()) + " shard(s), 0 compiled";
    std::printf("%s %s (%zu unique SPIR-V, %s%s%s) in %.0f ms with %u job(s)%s\n", a.out.empty() ? "built" : "wrote",
                what.c_str(), stats.uniqueSpirv, how.c_str(),
                stats.cacheCorrupt
                    ? (", " + std::to_string(stats.cacheCorrupt) + " corrupt cache entries rebuilt").c_str()
                    : "",
                remoteSummary(stats, remote.get()).c_str(), stats.wallMs,
                options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency()),
                a.out.empty() ? "" : (" to " + a.out).c_str());
  }
  return kExitOk;
}

Command addCompileCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "Compile materials, or exactly what a scene needs, into a package");
  cmd->add_option("materials", args->materials, kMaterialFilesHelp);
  cmd->add_option("--scene", args->scene, std::string(kSceneFileHelp) + "; compile exactly the permutations it needs");
  cmd->add_option(
      "-o,--output", args->out,
      "Package directory: created, filled when empty, or replaced atomically when it is a matbricks package; "
      "anything else is refused");
  cmd->add_flag("--explain", args->explain,
                "Print possible / required / compiled / unique counts and which axis multiplied them");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  args->axisOptions[0] =
      cmd->add_option("--lights", args->lights, "Light types every permutation shades (default: dir)")
          ->delimiter(',')
          ->check(CLI::IsMember(allLightTypes()));
  args->axisOptions[1] = cmd->add_option("--environment", args->environment, "Environment mode (default: none)")
                             ->check(CLI::IsMember(allEnvironmentModeNames()));
  args->axisOptions[2] =
      cmd->add_option("--precision", args->precision, "fp32 or fp16")->check(CLI::IsMember(allPrecisionNames()));
  args->axisOptions[3] = cmd->add_option("--quality", args->quality, "low, medium or high (default: high)")
                             ->check(CLI::IsMember(allQualityNames()));
  cmd->add_option(
         "--targets", args->targets,
         "Output languages (default: the scene's, else spirv): " +
             [] {
               std::string s;
               for (const auto& t : allTargetNames()) s += (s.empty() ? "" : ",") + t;
               return s;
             }())
      ->delimiter(',')
      ->check(CLI::IsMember(allTargetNames()));
  cmd->add_option("-O,--optimization", args->optimization,
                  "spirv-opt level of fp32 units: -O0 none, -O1 per-function clean-up without inlining, -O2 the "
                  "performance recipe (default: the scene's, else 2; docs/performance-compile.md \"Levels\")")
      ->check(CLI::IsMember({"0", "1", "2", "O0", "O1", "O2"}));
  cmd->add_option("--stages", args->stages,
                  "Shader stages the package holds: kernel, fragment or kernel,fragment (default: both; "
                  "docs/package.md \"Stages\")")
      ->check(CLI::Validator(
          [](std::string& text) {
            PackageStages stages;
            std::string why;
            return parsePackageStages(text, stages, why) ? std::string() : why;
          },
          "kernel,fragment"));
  cmd->add_option("-j,--jobs", args->jobs,
                  "Parallel compile jobs (default: every core); output is identical at every -j");
  cmd->add_option(
      "--cache-dir", args->cacheDir,
      "Compile cache directory (default: $MATBRICKS_CACHE_DIR, $XDG_CACHE_HOME/matbricks or ~/.cache/matbricks)");
  cmd->add_flag("--no-cache", args->noCache, "Neither read nor write the compile cache (local or remote)");
  cmd->add_option("--cache-url", args->cacheUrl,
                  "Remote compile cache behind the local one: an HTTP server taking GET/PUT of blobs (bazel-remote, "
                  "nginx WebDAV, ...); default $MATBRICKS_CACHE_URL");
  cmd->add_option("--cache-url-layout", args->cacheUrlLayout,
                  "Blob paths under --cache-url: subdirs (URL/ab/abcd...), flat (URL/abcd...) or bazel (URL/ac/...)")
      ->check(CLI::IsMember(remoteCacheLayouts()));
  cmd->add_option("--cache-timeout", args->cacheTimeout,
                  "Seconds a remote cache request may take before the remote cache is skipped (default 10)")
      ->check(CLI::Range(0.05, 3600.0));
  cmd->add_option("--cache-verify", args->cacheVerify,
                  "Fraction of remote cache hits (0..1, sampled by key) compiled again and compared byte for byte; "
                  "a difference is E-CACHE-VERIFY and drops the remote (default 0)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--stream-window", args->streamWindow,
                  "Permutations built per streamed window (default 256; 0: all at once). Memory grows with the "
                  "window, not the scene; output is identical at every window")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--shard", args->shard,
                  "Compile only shard i of N (i/N) of the required permutations into a shard directory; "
                  "'matbricks merge' joins the N shards into the package");
  cmd->add_option("--header", args->headerName, "Name of the generated C++ header (default: matbricks_materials.hpp)");
  cmd->add_option("--namespace", args->cppNamespace,
                  "C++ namespace of the generated header (default: matbricks_materials)");
  cmd->add_option(
      "--depfile", args->depfile,
      "Also write every file the compile read, in Makefile syntax, with the package's manifest.json as target");
  return {cmd, [args, &g] { return runCompile(*args, g); }};
}

}  // namespace mb::cli
