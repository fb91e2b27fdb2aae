// compile: buildPermutations (build.hpp, docs/targets.md "Parallel builds").
//
// 1. Emit every permutation on the calling thread (the library's source cache is not
//    thread-safe) and group identical emitted GLSL into one compile unit.
// 2. Key each unit for the cache (shader_cache.hpp) on the calling thread.
// 3. A pool of `jobs` threads takes units in order (under --shard i/N only the units whose
//    index is i-1 mod N): local cache lookup, else the remote cache, else glslang ->
//    spirv-val -> spirv-opt -> SPIRV-Cross targets -> checks -> reflection, then store in
//    both. `merge` instead takes every unit from the shards and compiles nothing. Every
//    entry, wherever it comes from, must carry the unit's own CacheIdentity.
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
#include "core/content_hash.hpp"
#include "emit/fragment_shader.hpp"

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
  // essl310; empty when the build makes none (BuildOptions::stages, Engine mode only).
  std::string fragmentGlsl, fragmentDisplayName, fragmentMediumpGlsl, fragmentMediumpDisplayName;
  // False: only the fragment shader is built (its text comes from the kernel's, `glsl`, which
  // also gives the include files).
  bool kernel = true;
  CompileOptions compile;
  // The build's level (BuildOptions::optimization). compile.optimization is O0 for fp16
  // kernels whatever it is; their mediump form for essl310 is compiled at this level.
  OptimizationLevel level = OptimizationLevel::O2;
  std::string cacheKey;
  CacheIdentity identity;  // cacheKey and the digest of the GLSL texts above
  // Results, written by one worker only.
  CompiledArtifacts artifacts;
  ShaderCache::Lookup lookup = ShaderCache::Lookup::Miss;  // Hit: from a cache or a shard
  ShaderCache::Lookup local = ShaderCache::Lookup::Miss;   // what the local cache had
  bool owned = true;                                       // built by this shard
  bool fromRemote = false, remoteCorrupt = false, remoteMismatch = false, uploaded = false;
  bool verified = false, verifyFailed = false;  // --cache-verify compiled this remote hit again
  std::string localWhy, remoteWhy;              // what was wrong with a bad entry or blob
  double compileMs = 0;
  std::vector<Diagnostic> errors;
  std::exception_ptr failure;  // anything that is not a DiagnosticError
};

// Non-spirv targets in allTargets() order, whatever order the caller listed them in.
std::vector<Target> crossTargets(const std::vector<Target>& requested) {
  std::vector<Target> out;
  for (Target t : allTargets())
    if (t != Target::Spirv && std::find(requested.begin(), requested.end(), t) != requested.end()) out.push_back(t);
  return out;
}

// Whether an fp16 unit needs its mediump form: a target without 16-bit floats is asked for.
bool needsMediump(const std::vector<Target>& targets) {
  return std::any_of(targets.begin(), targets.end(), [](Target t) { return !targetInfo(t).float16; });
}

// Everything that affects a unit's output (shader_cache.hpp).
std::string unitKey(const ShaderLibrary& lib, const EmittedShader& shader, const CompileOptions& co,
                    OptimizationLevel level, const std::vector<Target>& targets, const std::string& mediumpGlsl = "",
                    const CompileUnit* fragment = nullptr, bool kernel = true) {
  std::vector<std::string> parts{ShaderCache::kFormatVersion,
                                 MB_VERSION,
                                 toolchainVersion(),
                                 spirvCrossVersion(),
                                 optimizationCacheToken(co.optimization),
                                 co.validate ? "validate" : "no-validate"};
  // The build's level decides the mediump forms of fp16 units too (compiled at it, while the
  // kernel itself runs at O0). O2 adds no part, so keys from before levels stay valid.
  if (level != OptimizationLevel::O2) parts.push_back(std::string("level ") + optimizationLevelName(level));
  for (Target t : crossTargets(targets)) parts.push_back(targetName(t) + ": " + targetOptions(t));
  // Both stages add no part, so keys from before stage selection stay valid.
  if (!kernel) parts.push_back("no kernel");
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
  std::string where, why;
  switch (shards.load(u.identity, index, u.artifacts, where, why)) {
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
      u.errors.push_back(
          {Severity::Error,
           "E-SHARD-CORRUPT",
           {where, 0, 0},
           "the shard entry for '" + u.displayName + "' " + why + "; merge takes nothing from these shards",
           "compile that shard again"});
      return;
  }
}

// One stage: glslang -> spirv-val -> spirv-opt, every target (essl310 from the mediump form
// when there is one), reflection.
StageArtifacts compileStage(const std::string& glsl, const std::string& displayName, const std::string& mediumpGlsl,
                            const std::string& mediumpDisplayName, const CompileOptions& options,
                            OptimizationLevel mediumpLevel, const std::vector<Target>& targets) {
  StageArtifacts a;
  a.spirv = compileComputeGlsl(glsl, displayName, options).spirv;
  for (Target t : targets) {
    const std::string& name = targetName(t);
    if (options.stage == ShaderStage::Compute && !targetInfo(t).compute) continue;  // webgl2: fragment only
    if (!targetInfo(t).float16 && !mediumpGlsl.empty()) {
      // RelaxedPrecision survives spirv-opt's passes, and no 16-bit constant is involved.
      CompileOptions relaxed;
      relaxed.stage = options.stage;
      relaxed.pipeline = options.pipeline;
      relaxed.optimization = mediumpLevel;
      a.targets[name] =
          crossCompile(compileComputeGlsl(mediumpGlsl, mediumpDisplayName, relaxed).spirv, t, mediumpDisplayName);
    } else {
      a.targets[name] = crossCompile(a.spirv, t, displayName);
    }
  }
  a.reflection = reflectSpirv(a.spirv);
  return a;
}

// glslang and every target for the unit, timed.
CompiledArtifacts compileUnit(CompileUnit& u, const std::vector<Target>& targets) {
  auto t0 = Clock::now();
  CompiledArtifacts a;
  if (u.kernel)
    static_cast<StageArtifacts&>(a) =
        compileStage(u.glsl, u.displayName, u.mediumpGlsl, u.mediumpDisplayName, u.compile, u.level, targets);
  if (!u.fragmentGlsl.empty()) {
    CompileOptions fragment = u.compile;
    fragment.stage = ShaderStage::Fragment;
    a.fragment = compileStage(u.fragmentGlsl, u.fragmentDisplayName, u.fragmentMediumpGlsl,
                              u.fragmentMediumpDisplayName, fragment, u.level, targets);
  }
  a.includes = crossCompileIncludes(u.glsl, targets, u.displayName);
  u.compileMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  return a;
}

// The unit from the remote cache; false if it has to be compiled.
bool takeFromRemote(CompileUnit& u, const std::vector<Target>& targets, const UnitSources& src) {
  RemoteCache& remote = *src.remote;
  // A remote that always hits gives no local compile to compare its speed with: one unit is
  // compiled as a probe when its answers are slow (RemoteCache::wantsTimingProbe).
  if (remote.wantsTimingProbe()) return false;
  const RemoteCache::Get got = remote.get(u.identity, u.artifacts, &u.remoteWhy);
  u.remoteCorrupt = got == RemoteCache::Get::Corrupt;
  u.remoteMismatch = got == RemoteCache::Get::OtherUnit;
  if (got != RemoteCache::Get::Hit) return false;
  if (remote.verifies(u.cacheKey)) {
    // --cache-verify: a key is not a proof of content (docs/targets.md); compiling is
    // deterministic, so the remote's entry must equal a local compile byte for byte.
    const CompiledArtifacts local = compileUnit(u, targets);
    remote.noteCompile(u.compileMs);
    if (encodeCacheEntry(u.identity, local) != encodeCacheEntry(u.identity, u.artifacts)) {
      u.verifyFailed = true;
      remote.distrust("the remote cache's entry for '" + u.displayName + "' differs from its local compile");
      u.artifacts = local;
      return true;
    }
    u.verified = true;
  }
  u.lookup = ShaderCache::Lookup::Hit;
  u.fromRemote = true;
  src.cache.store(u.identity, u.artifacts);
  return true;
}

void buildUnit(CompileUnit& u, size_t index, const std::vector<Target>& targets, const UnitSources& src) {
  try {
    if (src.shards) return loadFromShards(u, index, *src.shards);
    const ShaderCache& cache = src.cache;
    u.local = cache.load(u.identity, u.artifacts, &u.localWhy);
    u.lookup = u.local;
    if (u.lookup == ShaderCache::Lookup::Hit) return;
    if (src.remote && takeFromRemote(u, targets, src)) return;
    CompiledArtifacts a = compileUnit(u, targets);
    cache.store(u.identity, a);
    if (src.remote) {
      src.remote->noteCompile(u.compileMs);
      u.uploaded = src.remote->put(u.identity, a);
    }
    u.artifacts = std::move(a);
  } catch (const DiagnosticError& e) {
    u.errors = e.diagnostics();
  } catch (...) {
    u.failure = std::current_exception();
  }
}

void runPool(std::vector<CompileUnit>& units, unsigned jobs, const std::vector<Target>& targets,
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

std::string buildCacheKey(const ShaderLibrary& lib, const EmittedShader& shader, OptimizationLevel optimization,
                          const std::vector<Target>& targets) {
  CompileOptions co;
  co.optimization = optimization;
  return unitKey(lib, shader, co, optimization, targets);
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
  size_t index = 0;    // in first-occurrence order: shards deal these out
  std::string source;  // CacheIdentity::source
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
        it->second.source = u.identity.source;
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
      b.unit = {unitKeys_[unit.index], unit.source};
      b.inShard = unit.owned;
      if (unit.owned) {
        const auto slot = freshSlot.find(&unit);
        if (slot != freshSlot.end()) {
          b.artifacts = fresh[slot->second].artifacts;
          b.compileMs = unit.reported || unit.lookup == ShaderCache::Lookup::Hit ? 0 : fresh[slot->second].compileMs;
        } else {
          if (unit.kernel.reflection) b.artifacts.reflection = *unit.kernel.reflection;
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
        hashes_.insert(b.spirvHash.empty() ? b.fragmentHash : b.spirvHash);
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
    // The remote served wrong code: nothing it supplied in this run stays in the local cache.
    if (verifyFailed_)
      for (const auto& key : unverifiedRemoteKeys_) cache_.evict(key);
    if (failure_) std::rethrow_exception(failure_);
    if (!errors_.empty()) throw DiagnosticError(errors_);
    s.uniqueSpirv = hashes_.size();
    if (options_.remote) s.remoteWarning = options_.remote->warning();
    s.cacheWarnings = cacheWarnings(s);
    if (stats) *stats = s;
  }

 private:
  CompileUnit unitFor(const Permutation& perm, const EmittedShader& shader) {
    CompileUnit u;
    // fp16 skips spirv-opt: SPIRV-Tools v2023.1's constant folding emits invalid 16-bit
    // constants (spirv-val then rejects the module), so fp16 ships glslang's SPIR-V as is.
    u.compile.optimization = perm.precision == Precision::Fp32 ? options_.optimization : OptimizationLevel::O0;
    u.level = options_.optimization;
    u.compile.pipeline = options_.pipeline;
    u.glsl = shader.glsl;
    u.displayName = shader.fileName;
    const bool engine = options_.mode == EmitMode::Engine;
    const bool fragment = options_.stages.fragment && engine;
    u.kernel = options_.stages.kernel || !engine;
    try {
      // The fragment shader (docs/fragment-stage.md) comes from the kernel's emitted text.
      if (fragment) setFragment(u, fragmentShaderOf(lib_, perm, shader, false), false);
      if (perm.precision == Precision::Fp16 && needsMediump(targets_)) {
        EmittedShader relaxed = emitPermutation(lib_, perm, false, options_.mode, true);
        if (fragment) setFragment(u, fragmentShaderOf(lib_, perm, relaxed, true), true);
        if (u.kernel) {
          u.mediumpGlsl = std::move(relaxed.glsl);
          u.mediumpDisplayName = relaxed.fileName;
        }
      }
    } catch (const DiagnosticError& e) {
      errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
    u.cacheKey = unitKey(lib_, shader, u.compile, u.level, targets_, u.mediumpGlsl, fragment ? &u : nullptr, u.kernel);
    u.identity = ShaderCache::identity(u.cacheKey, {u.glsl, u.mediumpGlsl, u.fragmentGlsl, u.fragmentMediumpGlsl});
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
    if (u.verifyFailed) {
      verifyFailed_ = true;
      errors_.push_back({Severity::Error,
                         "E-CACHE-VERIFY",
                         {options_.remote->displayUrl(), 0, 0},
                         "the remote cache's entry for '" + u.displayName + "' (key " + u.cacheKey +
                             ") differs from a local compile of the same unit: the remote cache serves wrong code. "
                             "Nothing was written; the remote cache is off and the entries it supplied in this run "
                             "were removed from the local cache",
                         "empty or repair the remote cache, or compile without --cache-url"});
    }
    if (u.fromRemote && !u.verified) unverifiedRemoteKeys_.push_back(u.cacheKey);
    noteFirst(firstLocalMismatch_, u.local == ShaderCache::Lookup::OtherUnit, u.localWhy);
    noteFirst(firstUnreadable_, u.local == ShaderCache::Lookup::Unreadable, u.localWhy);
    noteFirst(firstRemoteMismatch_, u.remoteMismatch, u.remoteWhy);
    if (!u.owned || u.failure || !u.errors.empty()) return;
    summary.lookup = u.lookup;
    summary.kernel = summarizeStage(u.artifacts);
    summary.fragment = summarizeStage(u.artifacts.fragment);
    ++stats_.shardUnits;
    stats_.compiled += u.lookup != ShaderCache::Lookup::Hit;
    stats_.cacheHits += u.lookup == ShaderCache::Lookup::Hit;
    stats_.cacheCorrupt += u.local == ShaderCache::Lookup::Corrupt;
    stats_.cacheMismatch += u.local == ShaderCache::Lookup::OtherUnit;
    stats_.cacheUnreadable += u.local == ShaderCache::Lookup::Unreadable;
    stats_.remoteHits += u.fromRemote;
    stats_.remoteCorrupt += u.remoteCorrupt;
    stats_.remoteMismatch += u.remoteMismatch;
    stats_.remoteVerified += u.verified;
    stats_.remoteUploads += u.uploaded;
  }

  static void noteFirst(std::string& first, bool happened, const std::string& why) {
    if (happened && first.empty()) first = why.empty() ? "?" : why;
  }

  // One warning per kind of bad entry, naming the first; the counts are in the stats.
  std::vector<Diagnostic> cacheWarnings(const BuildStats& s) const {
    std::vector<Diagnostic> out;
    auto warn = [&](size_t n, const char* code, const std::string& where, const char* what, const std::string& first,
                    const char* outcome) {
      if (n == 0) return;
      out.push_back({Severity::Warning,
                     code,
                     {where, 0, 0},
                     std::string(what) + " (" + std::to_string(n) + "): " + first +
                         (n > 1 ? " and " + std::to_string(n - 1) + " more" : "") + "; " + outcome,
                     ""});
    };
    const std::string local = cache_.dir().string();
    warn(s.cacheMismatch, "W-CACHE-MISMATCH", local, "local cache entries holding another unit's entry",
         firstLocalMismatch_, "evicted and rebuilt");
    warn(s.cacheUnreadable, "W-CACHE-UNREADABLE", local, "local cache entries not readable", firstUnreadable_,
         "evicted and rebuilt");
    if (!options_.remote) return out;
    const std::string remote = options_.remote->displayUrl();
    warn(s.remoteMismatch, "W-CACHE-REMOTE-MISMATCH", remote, "remote blobs holding another unit's entry",
         firstRemoteMismatch_, "ignored, compiled here, never stored in the local cache");
    if (!s.remoteWarning.empty())
      out.push_back({Severity::Warning, "W-CACHE-REMOTE", {remote, 0, 0}, s.remoteWarning, ""});
    return out;
  }

  const ShaderLibrary& lib_;
  const std::vector<Permutation>& perms_;
  const BuildOptions& options_;
  const std::vector<Target> targets_;
  const ShaderCache cache_;
  unsigned jobs_ = 1;
  std::unordered_map<std::string, UnitSummary> units_;  // by cache key
  std::vector<std::string> unitKeys_;                   // in first-occurrence order
  std::map<std::string, std::shared_ptr<const nlohmann::json>> reflections_;
  std::set<std::string> hashes_;
  std::vector<Diagnostic> errors_;
  std::exception_ptr failure_;
  bool emitFailed_ = false;
  bool verifyFailed_ = false;
  std::vector<std::string> unverifiedRemoteKeys_;  // units taken from the remote unchecked
  std::string firstLocalMismatch_, firstUnreadable_, firstRemoteMismatch_;
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
