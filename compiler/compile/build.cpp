// compile: buildPermutations (build.hpp, docs/targets.md "Parallel builds").
//
// 1. Emit every permutation on the calling thread (the library's source cache is not
//    thread-safe) and group identical emitted GLSL into one compile unit.
// 2. Key each unit for the cache (shader_cache.hpp) on the calling thread.
// 3. A pool of `jobs` threads takes units in order: cache lookup, else glslang -> spirv-val ->
//    spirv-opt -> SPIRV-Cross targets -> checks -> reflection, then store.
// Every output is a function of its unit alone, never of the schedule, so the results are
// bit-identical at every job count; they come back in input order.
#include "compile/build.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <set>
#include <thread>

#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "write/package_writer.hpp"

namespace mb {
namespace {

using Clock = std::chrono::steady_clock;

struct CompileUnit {
  std::string glsl;
  // fp16 units with the essl310 target: the same permutation as mediump GLSL
  // (emitPermutation's `mediump`), compiled separately for ESSL, which has no 16-bit types.
  std::string mediumpGlsl;
  std::string mediumpDisplayName;
  std::string displayName;  // of the first permutation that emitted it
  CompileOptions compile;
  std::string cacheKey;
  // Results, written by one worker only.
  CompiledArtifacts artifacts;
  ShaderCache::Lookup lookup = ShaderCache::Lookup::Miss;
  double compileMs = 0;
  std::vector<Diagnostic> errors;
  std::exception_ptr failure;  // anything that is not a DiagnosticError
};

// Non-spirv targets in allTargets() order, whatever order the caller listed them in.
std::vector<std::string> crossTargets(const std::vector<std::string>& requested) {
  std::vector<std::string> out;
  for (const auto& t : allTargets())
    if (t != "spirv" && std::find(requested.begin(), requested.end(), t) != requested.end()) out.push_back(t);
  return out;
}

// Everything that affects a unit's output (shader_cache.hpp).
std::string unitKey(const ShaderLibrary& lib, const EmittedShader& shader, const CompileOptions& co,
                    const std::vector<std::string>& targets, const std::string& mediumpGlsl = "") {
  std::vector<std::string> parts{ShaderCache::kFormatVersion,
                                 MB_VERSION,
                                 toolchainVersion(),
                                 spirvCrossVersion(),
                                 co.optimize ? "optimize" : "no-optimize",
                                 co.validate ? "validate" : "no-validate"};
  for (const auto& t : crossTargets(targets)) parts.push_back(t + ": " + targetOptions(t));
  parts.push_back(shader.glsl);
  parts.push_back(mediumpGlsl);
  for (const auto& id : shader.bricks) {
    parts.push_back(id);
    if (const Brick* b = lib.findBrick(id)) {
      const std::string& src = lib.source(b->file);
      parts.push_back(b->file + " " + contentHash(src.data(), src.size()));
    }
  }
  return ShaderCache::key(parts);
}

void buildUnit(CompileUnit& u, const std::vector<std::string>& targets, const ShaderCache& cache) {
  try {
    u.lookup = cache.load(u.cacheKey, u.artifacts);
    if (u.lookup == ShaderCache::Lookup::Hit) return;
    auto t0 = Clock::now();
    CompiledArtifacts a;
    a.spirv = compileComputeGlsl(u.glsl, u.displayName, u.compile).spirv;
    for (const auto& t : targets) {
      if (t == "essl310" && !u.mediumpGlsl.empty()) {
        // RelaxedPrecision survives spirv-opt's passes, and no 16-bit constant is involved.
        CompileOptions relaxed;
        relaxed.pipeline = u.compile.pipeline;
        a.targets[t] = crossCompile(compileComputeGlsl(u.mediumpGlsl, u.mediumpDisplayName, relaxed).spirv, t,
                                    u.mediumpDisplayName);
      } else {
        a.targets[t] = crossCompile(a.spirv, t, u.displayName);
      }
    }
    a.reflection = reflectSpirv(a.spirv);
    u.compileMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    cache.store(u.cacheKey, a);
    u.artifacts = std::move(a);
  } catch (const DiagnosticError& e) {
    u.errors = e.diagnostics();
  } catch (...) {
    u.failure = std::current_exception();
  }
}

void runPool(std::vector<CompileUnit>& units, unsigned jobs, const std::vector<std::string>& targets,
             const ShaderCache& cache) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next++) < units.size();) buildUnit(units[i], targets, cache);
  };
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();  // the calling thread is one of the jobs
  for (auto& t : pool) t.join();
}

}  // namespace

std::string buildCacheKey(const ShaderLibrary& lib, const EmittedShader& shader, bool optimize,
                          const std::vector<std::string>& targets) {
  CompileOptions co;
  co.optimize = optimize;
  return unitKey(lib, shader, co, targets);
}

std::vector<BuiltPermutation> buildPermutations(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                                const BuildOptions& options, BuildStats* stats) {
  const auto t0 = Clock::now();
  const std::vector<std::string> targets = crossTargets(options.targets);
  const ShaderCache cache(options.cacheDir);

  std::vector<BuiltPermutation> out(perms.size());
  std::vector<size_t> unitOf(perms.size());
  std::vector<CompileUnit> units;
  std::map<std::pair<bool, std::string>, size_t> unitByGlsl;
  std::vector<Diagnostic> errors;
  for (size_t i = 0; i < perms.size(); ++i) {
    try {
      out[i].shader = emitPermutation(lib, perms[i], false, options.mode);
    } catch (const DiagnosticError& e) {
      errors.insert(errors.end(), e.diagnostics().begin(), e.diagnostics().end());
      continue;
    }
    CompileOptions co;
    // fp16 skips spirv-opt: SPIRV-Tools v2023.1's constant folding emits invalid 16-bit
    // constants (spirv-val then rejects the module), so fp16 ships glslang's SPIR-V as is.
    co.optimize = perms[i].precision == "fp32";
    co.pipeline = options.pipeline;
    auto [it, fresh] = unitByGlsl.emplace(std::make_pair(co.optimize, out[i].shader.glsl), units.size());
    if (fresh) {
      CompileUnit u;
      u.glsl = out[i].shader.glsl;
      u.displayName = out[i].shader.fileName;
      u.compile = co;
      if (perms[i].precision == "fp16" && std::find(targets.begin(), targets.end(), "essl310") != targets.end()) {
        try {
          EmittedShader relaxed = emitPermutation(lib, perms[i], false, options.mode, true);
          u.mediumpGlsl = relaxed.glsl;
          u.mediumpDisplayName = relaxed.fileName;
        } catch (const DiagnosticError& e) {
          errors.insert(errors.end(), e.diagnostics().begin(), e.diagnostics().end());
        }
      }
      u.cacheKey = unitKey(lib, out[i].shader, co, targets, u.mediumpGlsl);
      units.push_back(std::move(u));
    }
    unitOf[i] = it->second;
  }
  if (!errors.empty()) throw DiagnosticError(errors);

  unsigned jobs = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<size_t>(jobs, std::max<size_t>(units.size(), 1)));
  runPool(units, jobs, targets, cache);

  for (const auto& u : units) {
    if (u.failure) std::rethrow_exception(u.failure);
    errors.insert(errors.end(), u.errors.begin(), u.errors.end());
  }
  if (!errors.empty()) throw DiagnosticError(errors);

  BuildStats s;
  s.permutations = perms.size();
  std::set<std::string> hashes;
  std::vector<bool> reported(units.size(), false);
  for (const auto& u : units) {
    s.compiled += u.lookup != ShaderCache::Lookup::Hit;
    s.cacheHits += u.lookup == ShaderCache::Lookup::Hit;
    s.cacheCorrupt += u.lookup == ShaderCache::Lookup::Corrupt;
  }
  for (size_t i = 0; i < perms.size(); ++i) {
    const CompileUnit& u = units[unitOf[i]];
    BuiltPermutation& b = out[i];
    b.artifacts = u.artifacts;
    b.spirvHash = contentHash(b.artifacts.spirv.data(), b.artifacts.spirv.size() * sizeof(uint32_t));
    b.fromCache = u.lookup == ShaderCache::Lookup::Hit;
    // A unit's compile time is reported once, on the first permutation that emitted it.
    b.compileMs = reported[unitOf[i]] || b.fromCache ? 0 : u.compileMs;
    reported[unitOf[i]] = true;
    hashes.insert(b.spirvHash);
  }
  s.uniqueSpirv = hashes.size();
  s.wallMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (stats) *stats = s;
  return out;
}

}  // namespace mb
