// compile: buildPermutations (build.hpp, docs/targets.md "Parallel builds").
//
// 1. Emit every permutation on the calling thread (the library's source cache is not
//    thread-safe) and group identical emitted GLSL into one compile unit.
// 2. Key each unit for the cache (shader_cache.hpp) on the calling thread.
// 3. A pool of `jobs` threads takes units in order (under --shard i/N only the units whose
//    index is i-1 mod N): local cache lookup, else the remote cache, else glslang ->
//    spirv-val -> spirv-opt -> SPIRV-Cross targets -> checks -> reflection, then store in
//    both. `merge` instead takes every unit from the shards and compiles nothing.
// Every output is a function of its unit alone, never of the schedule, so the results are
// bit-identical at every job count; they come back in input order.
#include "compile/build.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <map>
#include <set>
#include <memory>
#include <thread>
#include <unordered_map>

#include "compile/engine_includes.hpp"
#include "compile/glsl_compiler.hpp"
#include "compile/targets.hpp"
#include "emit/fragment_shader.hpp"
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
  // The fragment shader (docs/fragment-stage.md) and, like the kernel's, its mediump form for
  // essl310; empty when the build makes none (BuildOptions::fragment, Engine mode only).
  std::string fragmentGlsl, fragmentDisplayName, fragmentMediumpGlsl, fragmentMediumpDisplayName;
  CompileOptions compile;
  std::string cacheKey;
  // Results, written by one worker only.
  CompiledArtifacts artifacts;
  ShaderCache::Lookup lookup = ShaderCache::Lookup::Miss;
  bool owned = true;  // built by this shard
  bool fromRemote = false, remoteCorrupt = false, uploaded = false;
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
                    const std::vector<std::string>& targets, const std::string& mediumpGlsl = "",
                    const CompileUnit* fragment = nullptr) {
  std::vector<std::string> parts{ShaderCache::kFormatVersion,
                                 MB_VERSION,
                                 toolchainVersion(),
                                 spirvCrossVersion(),
                                 co.optimize ? "optimize" : "no-optimize",
                                 co.validate ? "validate" : "no-validate"};
  for (const auto& t : crossTargets(targets)) parts.push_back(t + ": " + targetOptions(t));
  parts.push_back(shader.glsl);
  parts.push_back(mediumpGlsl);
  if (fragment) {
    parts.push_back("fragment");
    parts.push_back(fragment->fragmentGlsl);
    parts.push_back(fragment->fragmentMediumpGlsl);
  }
  for (const auto& id : shader.bricks) {
    parts.push_back(id);
    if (const Brick* b = lib.findBrick(id)) {
      const std::string& src = lib.source(b->file);
      parts.push_back(b->file + " " + contentHash(src.data(), src.size()));
    }
  }
  return ShaderCache::key(parts);
}

// Where a unit's artifacts come from, in order: the shards (merge only), else the local
// cache, the remote cache, and a compile.
struct UnitSources {
  const ShaderCache& cache;
  RemoteCache* remote;
  const ShardSet* shards;
};

// merge: a unit's artifacts from the shards, or the error saying which shard lacks them.
void loadFromShards(CompileUnit& u, size_t index, const ShardSet& shards) {
  std::string where;
  switch (shards.load(u.cacheKey, index, u.artifacts, where)) {
    case ShardSet::Lookup::Hit:
      u.lookup = ShaderCache::Lookup::Hit;
      return;
    case ShardSet::Lookup::Missing:
      u.errors.push_back({Severity::Error,
                          "E-SHARD-MISSING",
                          {where, 0, 0},
                          "shard " + std::to_string(index % shards.count() + 1) + "/" + std::to_string(shards.count()) +
                              " has no entry for '" + u.displayName + "' (cache key " + u.cacheKey + ")",
                          "compile that shard again"});
      return;
    case ShardSet::Lookup::Corrupt:
      u.errors.push_back({Severity::Error,
                          "E-SHARD-CORRUPT",
                          {where, 0, 0},
                          "the shard entry for '" + u.displayName + "' is missing, truncated or damaged",
                          "compile that shard again"});
      return;
  }
}

// One stage: glslang -> spirv-val -> spirv-opt, every target (essl310 from the mediump form
// when there is one), reflection.
StageArtifacts compileStage(const std::string& glsl, const std::string& displayName, const std::string& mediumpGlsl,
                            const std::string& mediumpDisplayName, const CompileOptions& options,
                            const std::vector<std::string>& targets) {
  StageArtifacts a;
  a.spirv = compileComputeGlsl(glsl, displayName, options).spirv;
  for (const auto& t : targets) {
    if (t == "essl310" && !mediumpGlsl.empty()) {
      // RelaxedPrecision survives spirv-opt's passes, and no 16-bit constant is involved.
      CompileOptions relaxed;
      relaxed.stage = options.stage;
      relaxed.pipeline = options.pipeline;
      a.targets[t] =
          crossCompile(compileComputeGlsl(mediumpGlsl, mediumpDisplayName, relaxed).spirv, t, mediumpDisplayName);
    } else {
      a.targets[t] = crossCompile(a.spirv, t, displayName);
    }
  }
  a.reflection = reflectSpirv(a.spirv);
  return a;
}

void buildUnit(CompileUnit& u, size_t index, const std::vector<std::string>& targets, const UnitSources& src) {
  try {
    if (src.shards) return loadFromShards(u, index, *src.shards);
    const ShaderCache& cache = src.cache;
    u.lookup = cache.load(u.cacheKey, u.artifacts);
    if (u.lookup == ShaderCache::Lookup::Hit) return;
    if (src.remote) {
      const RemoteCache::Get got = src.remote->get(u.cacheKey, u.artifacts);
      u.remoteCorrupt = got == RemoteCache::Get::Corrupt;
      if (got == RemoteCache::Get::Hit) {
        u.lookup = ShaderCache::Lookup::Hit;
        u.fromRemote = true;
        cache.store(u.cacheKey, u.artifacts);
        return;
      }
    }
    auto t0 = Clock::now();
    CompiledArtifacts a;
    static_cast<StageArtifacts&>(a) =
        compileStage(u.glsl, u.displayName, u.mediumpGlsl, u.mediumpDisplayName, u.compile, targets);
    if (!u.fragmentGlsl.empty()) {
      CompileOptions fragment = u.compile;
      fragment.stage = ShaderStage::Fragment;
      a.fragment = compileStage(u.fragmentGlsl, u.fragmentDisplayName, u.fragmentMediumpGlsl,
                                u.fragmentMediumpDisplayName, fragment, targets);
    }
    a.includes = crossCompileIncludes(u.glsl, targets, u.displayName);
    u.compileMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    cache.store(u.cacheKey, a);
    if (src.remote) u.uploaded = src.remote->put(u.cacheKey, a);
    u.artifacts = std::move(a);
  } catch (const DiagnosticError& e) {
    u.errors = e.diagnostics();
  } catch (...) {
    u.failure = std::current_exception();
  }
}

void runPool(std::vector<CompileUnit>& units, unsigned jobs, const std::vector<std::string>& targets,
             const UnitSources& sources) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i; (i = next++) < units.size();)
      if (units[i].owned) buildUnit(units[i], i, targets, sources);
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

namespace {

// What later windows need of a unit built in an earlier one (a permutation whose emitted GLSL
// an earlier permutation already had): everything the package and manifest read, without the
// code itself, whose files the unit's first permutation already wrote.
struct StageSummary {
  std::string spirvHash;  // "" when the stage was not built
  size_t instructions = 0;
  std::shared_ptr<const nlohmann::json> reflection;  // interned: few distinct ones
  std::vector<std::string> targets;                  // names of the non-spirv targets built
};

struct UnitSummary {
  size_t index = 0;  // in first-occurrence order: shards deal these out
  bool owned = true;
  bool reported = false;  // its compile time was reported on its first permutation
  ShaderCache::Lookup lookup = ShaderCache::Lookup::Miss;
  StageSummary kernel, fragment;
};

// One window of permutations: emitted on the calling thread, its new units compiled by the
// pool, then handed to the sink in order.
class StreamingBuild {
 public:
  StreamingBuild(const ShaderLibrary& lib, const std::vector<Permutation>& perms, const BuildOptions& options)
      : lib_(lib), perms_(perms), options_(options), targets_(crossTargets(options.targets)), cache_(options.cacheDir) {
    jobs_ = options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  }

  void run(size_t first, size_t last, const BuiltSink& sink) {
    std::vector<EmittedShader> shaders(last - first);
    std::vector<UnitSummary*> unitOf(last - first, nullptr);
    std::vector<CompileUnit> fresh;
    std::map<UnitSummary*, size_t> freshSlot;
    for (size_t i = first; i < last; ++i) {
      try {
        shaders[i - first] = emitPermutation(lib_, perms_[i], false, options_.mode);
      } catch (const DiagnosticError& e) {
        emitFailed_ = true;
        errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
        continue;
      }
      CompileUnit u = unitFor(perms_[i], shaders[i - first]);
      auto [it, isNew] = units_.try_emplace(u.cacheKey);
      if (isNew) {
        it->second.index = unitKeys_.size();
        it->second.owned = options_.shard.owns(it->second.index);
        u.owned = it->second.owned;
        unitKeys_.push_back(u.cacheKey);
        freshSlot[&it->second] = fresh.size();
        fresh.push_back(std::move(u));
      }
      unitOf[i - first] = &it->second;
    }
    // As before streaming: an emission error stops compiling, the rest is still emitted so
    // that every emission error is reported at once.
    if (emitFailed_) return;
    const unsigned jobs = static_cast<unsigned>(std::min<size_t>(jobs_, std::max<size_t>(fresh.size(), 1)));
    runPool(fresh, jobs, targets_, {cache_, options_.remote, options_.mergeFrom});
    for (auto& [summary, slot] : freshSlot) summarize(*summary, fresh[slot]);
    if (!errors_.empty()) return;
    for (size_t i = first; i < last; ++i) {
      UnitSummary& unit = *unitOf[i - first];
      BuiltPermutation b;
      b.shader = std::move(shaders[i - first]);
      b.cacheKey = unitKeys_[unit.index];
      b.inShard = unit.owned;
      if (unit.owned) {
        const auto slot = freshSlot.find(&unit);
        if (slot != freshSlot.end()) {
          b.artifacts = fresh[slot->second].artifacts;
          b.compileMs = unit.reported || unit.lookup == ShaderCache::Lookup::Hit ? 0 : fresh[slot->second].compileMs;
        } else {
          b.artifacts.reflection = *unit.kernel.reflection;
          for (const auto& t : unit.kernel.targets) b.artifacts.targets[t];
          if (unit.fragment.reflection) b.artifacts.fragment.reflection = *unit.fragment.reflection;
          for (const auto& t : unit.fragment.targets) b.artifacts.fragment.targets[t];
        }
        unit.reported = true;
        b.spirvHash = unit.kernel.spirvHash;
        b.spirvInstructions = unit.kernel.instructions;
        b.fragmentHash = unit.fragment.spirvHash;
        b.fragmentInstructions = unit.fragment.instructions;
        b.fromCache = unit.lookup == ShaderCache::Lookup::Hit;
        hashes_.insert(b.spirvHash);
      }
      sink(i, b);
    }
  }

  void finish(BuildStats* stats) {
    BuildStats s = stats_;
    s.permutations = perms_.size();
    s.units = unitKeys_.size();
    const unsigned splitInto = options_.mergeFrom ? options_.mergeFrom->count() : std::max(options_.shard.count, 1u);
    s.planDigest = planDigest(splitInto, unitKeys_);
    // Shards of another build lack units: say that, not which entries are missing.
    if (options_.mergeFrom && !emitFailed_) options_.mergeFrom->requirePlan(s.planDigest);
    if (failure_) std::rethrow_exception(failure_);
    if (!errors_.empty()) throw DiagnosticError(errors_);
    s.uniqueSpirv = hashes_.size();
    if (options_.remote) s.remoteWarning = options_.remote->warning();
    if (stats) *stats = s;
  }

 private:
  CompileUnit unitFor(const Permutation& perm, const EmittedShader& shader) {
    CompileUnit u;
    // fp16 skips spirv-opt: SPIRV-Tools v2023.1's constant folding emits invalid 16-bit
    // constants (spirv-val then rejects the module), so fp16 ships glslang's SPIR-V as is.
    u.compile.optimize = perm.precision == "fp32";
    u.compile.pipeline = options_.pipeline;
    u.glsl = shader.glsl;
    u.displayName = shader.fileName;
    const bool fragment = options_.fragment && options_.mode == EmitMode::Engine;
    try {
      // The fragment shader (docs/fragment-stage.md) comes from the kernel's emitted text.
      if (fragment) setFragment(u, fragmentShaderOf(lib_, perm, shader, false), false);
      if (perm.precision == "fp16" && std::find(targets_.begin(), targets_.end(), "essl310") != targets_.end()) {
        EmittedShader relaxed = emitPermutation(lib_, perm, false, options_.mode, true);
        if (fragment) setFragment(u, fragmentShaderOf(lib_, perm, relaxed, true), true);
        u.mediumpGlsl = std::move(relaxed.glsl);
        u.mediumpDisplayName = relaxed.fileName;
      }
    } catch (const DiagnosticError& e) {
      errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
    u.cacheKey = unitKey(lib_, shader, u.compile, targets_, u.mediumpGlsl, fragment ? &u : nullptr);
    return u;
  }

  static void setFragment(CompileUnit& u, EmittedShader fragment, bool mediump) {
    (mediump ? u.fragmentMediumpGlsl : u.fragmentGlsl) = std::move(fragment.glsl);
    (mediump ? u.fragmentMediumpDisplayName : u.fragmentDisplayName) = fragment.fileName;
  }

  // What later windows need of one stage of a unit.
  StageSummary summarizeStage(const StageArtifacts& a) {
    StageSummary s;
    if (a.spirv.empty()) return s;
    s.spirvHash = contentHash(a.spirv.data(), a.spirv.size() * sizeof(uint32_t));
    s.instructions = spirvInstructionCount(a.spirv);
    const std::string text = a.reflection.dump();
    auto [it, isNew] = reflections_.try_emplace(text);
    if (isNew) it->second = std::make_shared<const nlohmann::json>(a.reflection);
    s.reflection = it->second;
    for (const auto& [t, code] : a.targets) s.targets.push_back(t);
    return s;
  }

  void summarize(UnitSummary& summary, const CompileUnit& u) {
    if (u.failure && !failure_) failure_ = u.failure;
    errors_.insert(errors_.end(), u.errors.begin(), u.errors.end());
    if (!u.owned || u.failure || !u.errors.empty()) return;
    summary.lookup = u.lookup;
    summary.kernel = summarizeStage(u.artifacts);
    summary.fragment = summarizeStage(u.artifacts.fragment);
    ++stats_.shardUnits;
    stats_.compiled += u.lookup != ShaderCache::Lookup::Hit;
    stats_.cacheHits += u.lookup == ShaderCache::Lookup::Hit;
    stats_.cacheCorrupt += u.lookup == ShaderCache::Lookup::Corrupt;
    stats_.remoteHits += u.fromRemote;
    stats_.remoteCorrupt += u.remoteCorrupt;
    stats_.remoteUploads += u.uploaded;
  }

  const ShaderLibrary& lib_;
  const std::vector<Permutation>& perms_;
  const BuildOptions& options_;
  const std::vector<std::string> targets_;
  const ShaderCache cache_;
  unsigned jobs_ = 1;
  std::unordered_map<std::string, UnitSummary> units_;  // by cache key
  std::vector<std::string> unitKeys_;                   // in first-occurrence order
  std::map<std::string, std::shared_ptr<const nlohmann::json>> reflections_;
  std::set<std::string> hashes_;
  std::vector<Diagnostic> errors_;
  std::exception_ptr failure_;
  bool emitFailed_ = false;
  BuildStats stats_;
};

}  // namespace

void buildPermutationsStreaming(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                const BuildOptions& options, const BuiltSink& sink, BuildStats* stats) {
  const auto t0 = Clock::now();
  StreamingBuild build(lib, perms, options);
  const size_t window = options.window ? options.window : std::max<size_t>(perms.size(), 1);
  for (size_t first = 0; first < perms.size(); first += window)
    build.run(first, std::min(perms.size(), first + window), sink);
  BuildStats s;
  build.finish(&s);
  s.wallMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  if (stats) *stats = s;
}

std::vector<BuiltPermutation> buildPermutations(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                                const BuildOptions& options, BuildStats* stats) {
  BuildOptions whole = options;
  whole.window = 0;  // one window: every permutation gets its unit's full artifacts
  std::vector<BuiltPermutation> out(perms.size());
  buildPermutationsStreaming(
      lib, perms, whole, [&](size_t i, BuiltPermutation& b) { out[i] = std::move(b); }, stats);
  return out;
}

}  // namespace mb
