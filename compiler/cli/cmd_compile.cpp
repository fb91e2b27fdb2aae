// matbricks compile: parses the command line into a CompileRequest, runs it
// (driver/compile_run.hpp: materials or a scene -> the required permutations -> built in
// parallel through the cache, to every target -> a package written atomically) and prints what
// it built (docs/cli.md, docs/scenes.md, docs/targets.md, docs/package.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli/cli_common.hpp"
#include "cli/compile_run.hpp"
#include "compile/remote_cache.hpp"
#include "core/package_stages.hpp"
#include "core/vocabulary.hpp"
#include "driver/compile_run.hpp"

namespace mb::cli {
namespace {

std::string remoteSummary(const BuildStats& s, bool remote) {
  if (!remote) return "";
  std::string text = ", " + std::to_string(s.remoteHits) + " of them from the remote cache, " +
                     std::to_string(s.remoteUploads) + " uploaded";
  if (s.remoteCorrupt) text += ", " + std::to_string(s.remoteCorrupt) + " corrupt remote blob(s) ignored";
  if (s.remoteMismatch) text += ", " + std::to_string(s.remoteMismatch) + " remote blob(s) of another unit ignored";
  if (s.remoteVerified) text += ", " + std::to_string(s.remoteVerified) + " verified by compiling again";
  return text;
}

}  // namespace

int runCompile(const CompileArgs& args, const GlobalOptions& g, const ShardSet* mergeFrom,
               const std::vector<ProtectedPath>& protectedInputs) {
  const CompileRequest& a = args.request;
  // Usage errors exit 2 (CLI::ValidationError), as CLI11's own do. With both materials and a
  // scene the driver's "either ... or" is the error, as it was before this check.
  if (!a.scene.empty() && a.materials.empty())
    for (const CLI::Option* o : args.axisOptions)
      if (o && o->count() > 0)
        throw CLI::ValidationError(o->get_name() +
                                   " conflicts with --scene: the scene file sets that axis (docs/scenes.md)");
  // `--targets spirv hlsl` or `--lights dir point`: the list ends at the space, and the rest would
  // be read as material files. A name of the option's values that is no file is that mistake.
  for (const auto& m : a.materials) {
    if (std::filesystem::exists(m)) continue;
    const bool target = parseTarget(m).has_value(), light = parseLightType(m).has_value();
    if (target || light)
      throw CLI::ValidationError("'" + m + "' is a " + (target ? "target" : "light type") + ", not a material file: " +
                                 (target ? "--targets" : "--lights") + " takes one comma-separated list (e.g. " +
                                 (target ? "--targets spirv," : "--lights dir,") + m + ")");
  }
  CompileHooks hooks;
  hooks.warnings = [&](const std::vector<Diagnostic>& w) { printDiagnostics(w, g); };
  hooks.built = [&](const BuiltPermutation& b) {
    if (a.quiet || a.explain) return;
    // The kernel's module, else (fragment only) the fragment shader's.
    const bool kernel = !b.spirvHash.empty();
    std::printf("compiled %-52s %7.2f ms  %5zu instructions  %s%s\n", b.shader.key.c_str(), b.compileMs,
                kernel ? b.spirvInstructions : b.fragmentInstructions, (kernel ? b.spirvHash : b.fragmentHash).c_str(),
                b.fromCache ? (mergeFrom ? "  (from its shard)" : "  (cached)") : "");
  };
  hooks.explain = [](const std::string& text) { std::fputs(text.c_str(), stdout); };
  CompileOutcome outcome;
  try {
    outcome = mb::runCompile(a, hooks, mergeFrom, protectedInputs);
  } catch (const CompileUsageError& e) {
    throw CLI::ValidationError(e.what());
  }
  if (!a.quiet) {
    const BuildStats& stats = outcome.stats;
    const ShardSpec& shard = outcome.shard;
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
                remoteSummary(stats, outcome.remote).c_str(), stats.wallMs,
                outcome.jobs ? outcome.jobs : std::max(1u, std::thread::hardware_concurrency()),
                a.out.empty() ? "" : (" to " + a.out).c_str());
  }
  return kExitOk;
}

Command addCompileCommand(CLI::App& app, GlobalOptions& g) {
  auto args = std::make_shared<CompileArgs>();
  CLI::App* cmd = app.add_subcommand("compile", "Compile materials, or exactly what a scene needs, into a package");
  cmd->add_option("materials", args->request.materials, kMaterialFilesHelp);
  cmd->add_option("--scene", args->request.scene,
                  std::string(kSceneFileHelp) + "; compile exactly the permutations it needs");
  cmd->add_option(
      "-o,--output", args->request.out,
      "Package directory: created, filled when empty, or replaced atomically when it is a matbricks package; "
      "anything else is refused");
  cmd->add_flag("--explain", args->request.explain,
                "Print possible / required / compiled / unique counts and which axis multiplied them");
  cmd->add_flag("-q,--quiet", args->request.quiet, "Print nothing on success");
  args->axisOptions[0] =
      cmd->add_option("--lights", args->lights, "Light types every permutation shades (default: dir)")
          ->delimiter(',')
          ->check(CLI::IsMember(allLightTypeNames()));
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
  cmd->add_option("-O,--optimization", args->request.optimization,
                  "spirv-opt level of fp32 units: -O0 none, -O1 per-function clean-up without inlining, -O2 the "
                  "performance recipe (default: the scene's, else 2; docs/performance-compile.md \"Levels\")")
      ->check(CLI::IsMember({"0", "1", "2", "O0", "O1", "O2"}));
  cmd->add_option("--stages", args->request.stages,
                  "Shader stages the package holds: kernel, fragment or kernel,fragment (default: both; "
                  "docs/package.md \"Stages\")")
      ->check(CLI::Validator(
          [](std::string& text) {
            PackageStages stages;
            std::string why;
            return parsePackageStages(text, stages, why) ? std::string() : why;
          },
          "kernel,fragment"));
  cmd->add_option("-j,--jobs", args->request.jobs,
                  "Parallel compile jobs (default: every core); output is identical at every -j");
  cmd->add_option(
      "--cache-dir", args->request.cacheDir,
      "Compile cache directory (default: $MATBRICKS_CACHE_DIR, $XDG_CACHE_HOME/matbricks or ~/.cache/matbricks)");
  cmd->add_flag("--no-cache", args->request.noCache, "Neither read nor write the compile cache (local or remote)");
  cmd->add_option("--cache-url", args->request.cacheUrl,
                  "Remote compile cache behind the local one: an HTTP server taking GET/PUT of blobs (bazel-remote, "
                  "nginx WebDAV, ...); default $MATBRICKS_CACHE_URL");
  cmd->add_option("--cache-url-layout", args->request.cacheUrlLayout,
                  "Blob paths under --cache-url: subdirs (URL/ab/abcd...), flat (URL/abcd...) or bazel (URL/ac/...)")
      ->check(CLI::IsMember(remoteCacheLayouts()));
  cmd->add_option("--cache-timeout", args->request.cacheTimeout,
                  "Seconds a remote cache request may take before the remote cache is skipped (default 10)")
      ->check(CLI::Range(0.05, 3600.0));
  cmd->add_option("--cache-verify", args->request.cacheVerify,
                  "Fraction of remote cache hits (0..1, sampled by key) compiled again and compared byte for byte; "
                  "a difference is E-CACHE-VERIFY and drops the remote (default 0)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--stream-window", args->request.streamWindow,
                  "Permutations built per streamed window (default 256; 0: all at once). Memory grows with the "
                  "window, not the scene; output is identical at every window")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--shard", args->request.shard,
                  "Compile only shard i of N (i/N) of the required permutations into a shard directory; "
                  "'matbricks merge' joins the N shards into the package");
  cmd->add_option("--header", args->request.headerName,
                  "Name of the generated C++ header (default: matbricks_materials.hpp)");
  cmd->add_option("--namespace", args->request.cppNamespace,
                  "C++ namespace of the generated header (default: matbricks_materials)");
  cmd->add_option(
      "--depfile", args->request.depfile,
      "Also write every file the compile read, in Makefile syntax, with the package's manifest.json as target");
  return {cmd, [args, &g] {
            args->request.shaderlib = g.shaderlib;
            args->request.lights = parseLightTypes(args->lights);                  // checked by --lights's IsMember
            args->request.environment = *parseEnvironmentMode(args->environment);  // and --environment's
            args->request.precision = *parsePrecision(args->precision);            // --precision's
            args->request.quality = *parseQuality(args->quality);                  // --quality's
            args->request.targets = parseTargets(args->targets);                   // --targets'
            return runCompile(*args, g);
          }};
}

}  // namespace mb::cli
