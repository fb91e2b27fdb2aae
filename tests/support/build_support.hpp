// Shared by test_build.cpp, test_cache.cpp and test_targets.cpp: example permutations built
// through compile/build.hpp, scratch directories, artifact comparison.
#pragma once
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "compile/build.hpp"
#include "support/material_fixtures.hpp"
#include "support/pipeline_support.hpp"

namespace mb::test {

// The root of a scratch directory (material_fixtures.hpp); tests never touch the user's cache.
inline std::filesystem::path rootOf(const ScratchDir& dir) { return std::filesystem::path(dir.path("")).parent_path(); }

// Materials loaded once and kept alive (permutations point at them).
inline const std::vector<MaterialDesc>& loadedMaterials(const ShaderLibrary& lib,
                                                        const std::vector<std::string>& names) {
  static std::vector<std::unique_ptr<std::vector<MaterialDesc>>> keep;
  auto owned = std::make_unique<std::vector<MaterialDesc>>();
  for (const auto& n : names)
    owned->push_back(loadMaterialJson((sourceDir() / "materials" / (n + ".json")).string(), lib));
  keep.push_back(std::move(owned));
  return *keep.back();
}

// One permutation per material, on the given axes.
inline std::vector<Permutation> permutationsOf(const std::vector<MaterialDesc>& materials,
                                               const std::vector<std::string>& lights, EnvironmentMode environment,
                                               Precision precision = Precision::Fp32) {
  std::vector<Permutation> out;
  for (const auto& m : materials) {
    Permutation p;
    p.material = &m;
    p.lights = canonicalLights(parseLightTypes(lights));
    p.environment = environment;
    p.precision = precision;
    out.push_back(p);
  }
  return out;
}

// Every byte of two builds' outputs, compared permutation by permutation.
inline void requireIdentical(const std::vector<BuiltPermutation>& a, const std::vector<BuiltPermutation>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    INFO(a[i].shader.key);
    CHECK(a[i].shader.key == b[i].shader.key);
    CHECK(a[i].artifacts.spirv == b[i].artifacts.spirv);
    CHECK(a[i].artifacts.targets == b[i].artifacts.targets);
    CHECK(a[i].artifacts.reflection.dump() == b[i].artifacts.reflection.dump());
    CHECK(a[i].spirvHash == b[i].spirvHash);
    CHECK(a[i].artifacts.fragment.spirv == b[i].artifacts.fragment.spirv);
    CHECK(a[i].artifacts.fragment.targets == b[i].artifacts.fragment.targets);
    CHECK(a[i].artifacts.fragment.reflection.dump() == b[i].artifacts.fragment.reflection.dump());
    CHECK(a[i].fragmentHash == b[i].fragmentHash);
  }
}

}  // namespace mb::test
