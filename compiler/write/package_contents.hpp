// write: what goes into a package besides nothing (docs/package.md):
//   manifest.json                 keys, hashes, bricks, parameters, SPIRV-Cross reflection,
//                                 record layout, the scene's axes and counts
//   spirv/<hash>.spv              one file per distinct SPIR-V (deduplicated by hash)
//   <target>/<hash><ext>          the same for every other target requested
//   include/<key>.glsl            per permutation, a self-contained GLSL include (no #line,
//                                 no probe; the engine supplies the fetch hooks)
//   <header>                      C++17 header: per distinct parameter block a std140 struct
//                                 with static_asserts on every offset (from the reflection),
//                                 and a constexpr table of permutation keys -> SPIR-V file
#pragma once
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "core/target.hpp"
#include "library/shader_library.hpp"
#include "permute/scene_plan.hpp"
#include "write/package_writer.hpp"

namespace mb {

struct PackageInputs {
  const ShaderLibrary* lib = nullptr;
  const ScenePlan* plan = nullptr;
  const std::vector<BuiltPermutation>* built = nullptr;  // same order as plan->required
  std::vector<Target> targets{Target::Spirv};
  OptimizationLevel optimization = OptimizationLevel::O2;  // the build's (BuildOptions::optimization)
  PackageStages stages;                                    // the build's (BuildOptions::stages)
  std::string sceneFile;                                   // empty for `compile MATERIAL...`
  std::string headerName = "matbricks_materials.hpp";
  std::string cppNamespace = "matbricks_materials";
};

class ManifestWriter;
class HeaderWriter;

// The package, one permutation at a time, as a streaming build hands them over
// (build.hpp buildPermutationsStreaming): each permutation's files go to `pkg` at once (into
// its staging directory when pkg.stage() was called), and only what the manifest and header
// need of it is kept, on disk. `in.built` is not used.
class PackageStream {
 public:
  PackageStream(PackageWriter& pkg, const PackageInputs& in);
  ~PackageStream();
  // In plan order; `perm` and `built` need only live during the call.
  void add(const Permutation& perm, const BuiltPermutation& built);
  // manifest.json and the header; then the caller commits `pkg`.
  void finish();

 private:
  PackageWriter& pkg_;
  const PackageInputs& in_;
  std::set<std::string> written_;  // SPIR-V hashes whose files are already added
  std::unique_ptr<ManifestWriter> manifest_;
  std::unique_ptr<HeaderWriter> header_;
};

// Adds every file above to `pkg` for a whole build (`in.built`); the caller commits it.
void addPackageFiles(PackageWriter& pkg, const PackageInputs& in);

}  // namespace mb
