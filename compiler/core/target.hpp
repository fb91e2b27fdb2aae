// The output languages of a permutation (DESIGN.md vocabulary "target"), as a type and one
// table of what each is: its name (command line, scenes, manifests, package directories), its
// file extensions, the language SPIRV-Cross writes it in and the checker that reads it back,
// its version and options, and whether it has 16-bit floats. Names are parsed once where they
// enter (the command line, a scene, a shard); everything after that takes a Target, and
// compile/targets.cpp looks the rest up here (docs/architecture.md "Adding a target").
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mb {

// In package order: the manifest's "targets", a package's files and the cache key list them so.
enum class Target { Spirv, Glsl450, Essl310, Hlsl, Msl, Webgl2 };

// The language a target is written in: SPIRV-Cross's backend for it and its checker
// (compile/target_checks.hpp). Spirv is glslang's own output, checked by spirv-val.
enum class TargetLanguage { Spirv, Glsl, Hlsl, Msl };

struct TargetInfo {
  Target target;
  const char* name;
  const char* kernelExtension;    // of the compute kernel's file in the package ("": no kernel)
  const char* fragmentExtension;  // of the fragment shader's file in the package
  TargetLanguage language;
  bool es;  // Glsl: the ES profile (#version 310 es, 300 es)
  // GLSL/ESSL #version, HLSL shader model (60 = 6.0), MSL SPVC_MAKE_MSL_VERSION (20300 = 2.3.0).
  unsigned version;
  // False: the language has no 16-bit float type, so an fp16 permutation is cross-compiled
  // from its mediump form (emit/emitter.hpp emitPermutation's `mediump`) instead.
  bool float16;
  // The options the cross-compiler is given, after the language and version, as one line for
  // the cache key (compile/targets.hpp targetOptions).
  const char* optionFlags;
  // The engine include's extension (include/<key><ext>, compile/engine_includes.hpp), made
  // for this target when it is asked for; "" when the target has none of its own.
  const char* includeExtension;
  // False: the language has no compute shaders (WebGL2's ESSL 3.00), so only the fragment
  // stage is built for it, and with it the reference vertex shader (compile/webgl2.hpp).
  bool compute = true;
};

const TargetInfo& targetInfo(Target t);
// The row of a name the program itself wrote (a key of CompiledArtifacts' maps, which the
// cache stores by name); throws std::logic_error for any other name.
const TargetInfo& targetInfo(std::string_view name);
const std::string& targetName(Target t);
// Every target, in package order.
const std::vector<Target>& allTargets();
// Their names, in the same order (what the command line and a scene accept).
const std::vector<std::string>& allTargetNames();
// nullopt for a name that is not a target.
std::optional<Target> parseTarget(std::string_view name);
// Names already checked against allTargetNames() (by the command line or the scene loader).
std::vector<Target> parseTargets(const std::vector<std::string>& names);
std::vector<std::string> targetNames(const std::vector<Target>& targets);

}  // namespace mb
