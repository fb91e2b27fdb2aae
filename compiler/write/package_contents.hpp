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
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "library/shader_library.hpp"
#include "permute/scene_plan.hpp"
#include "write/package_writer.hpp"

namespace mb {

struct PackageInputs {
  const ShaderLibrary* lib = nullptr;
  const ScenePlan* plan = nullptr;
  const std::vector<BuiltPermutation>* built = nullptr;  // same order as plan->required
  std::vector<std::string> targets{"spirv"};
  std::string sceneFile;  // empty for `compile MATERIAL...`
  std::string headerName = "matbricks_materials.hpp";
  std::string cppNamespace = "matbricks_materials";
};

// Adds every file above to `pkg`; the caller commits it atomically.
void addPackageFiles(PackageWriter& pkg, const PackageInputs& in);

}  // namespace mb
