// What one `compile` (or `merge`) is asked to do, as plain data: the command line fills it,
// a shard's shard.json records the part that decides the package's bytes and `merge` reads it
// back, and a test or a benchmark fills it directly (driver/compile_run.hpp runs it).
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/diagnostics.hpp"
#include "core/environment_mode.hpp"
#include "core/light_type.hpp"
#include "core/precision.hpp"
#include "core/quality.hpp"
#include "core/target.hpp"

namespace mb {

// What was asked (docs/cli.md `compile` gives each field's meaning and default). The axes and the
// targets are values, parsed where they enter (the command line, a shard's shard.json); the
// optimization level and the stages are kept as written (shard.json records them so) and
// runCompile() parses them once.
struct CompileRequest {
  std::vector<std::string> materials;  // material files; or
  std::string scene;                   // a scene file (exactly one of the two)
  std::string out;                     // package (or shard) directory; empty: build only (explain)
  bool quiet = false;
  bool explain = false;
  std::vector<LightType> lights{LightType::Dir};
  EnvironmentMode environment = EnvironmentMode::None;
  Precision precision = Precision::Fp32;
  Quality quality = Quality::High;
  std::vector<Target> targets;  // empty: the scene's, else spirv
  std::string optimization;     // "0".."2" or "O0".."O2"; empty: the scene's, else O2
  std::string stages;           // "kernel", "fragment" or both; empty: both
  unsigned jobs = 0;            // 0: every core
  std::string cacheDir;         // empty: the default (ShaderCache::defaultDir())
  bool noCache = false;
  std::string cacheUrl;  // empty: $MATBRICKS_CACHE_URL, else none
  std::string cacheUrlLayout = "subdirs";
  double cacheTimeout = 10;
  double cacheVerify = 0;  // fraction of remote hits compiled again and compared
  std::string shard;       // "i/N"; empty: the whole build
  // Permutations emitted and compiled per streamed window (docs/targets.md "Memory"): enough
  // units to keep every job busy between windows, few enough that a window's GLSL and
  // artifacts stay a few tens of MB. 0: the whole build at once.
  size_t streamWindow = 256;
  std::string headerName = "matbricks_materials.hpp";
  std::string cppNamespace = "matbricks_materials";
  std::string depfile;
  std::string shaderlib;  // the shader library's root; empty: ShaderLibrary::defaultRoot()
};

// The fields that decide a package's bytes (not the output, jobs, caches or verbosity), as a
// shard's shard.json records them ("command"), and back.
nlohmann::json compileRequestJson(const CompileRequest& r);
// Fills those fields of `r`; throws DiagnosticError (E-SHARD-NOT-SHARD, or the code an unknown
// axis value has on the command line, at `file`) for a command object it cannot read.
void compileRequestFromJson(const nlohmann::json& command, const std::string& file, CompileRequest& r);

// --header names one file at the package's top level (docs/package.md): a plain name, and not
// one the package itself writes there. Throws DiagnosticError at `at`.
void checkHeaderName(const std::string& name, const SourceLocation& at);

}  // namespace mb
