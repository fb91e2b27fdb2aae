// buildPermutations (compile/build.hpp): parallel, deduplicated, deterministic, all-or-nothing.
#include <catch2/catch.hpp>

#include <fstream>

#include <spirv-tools/libspirv.hpp>

#include "compile/targets.hpp"
#include "write/package_contents.hpp"
#include "support/build_support.hpp"

using namespace mb;
namespace fs = std::filesystem;

TEST_CASE("output is bit-identical at -j1 and -j4, every target", "[build]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const auto& mats = test::loadedMaterials(lib, {"brushed_metal", "clearcoat_metal", "filament_plastic", "satin_sheen",
                                                 "worn_car_paint", "frostbite_dielectric"});
  auto perms = test::permutationsOf(mats, {"dir", "point", "sphere"}, EnvironmentMode::IblLut);
  for (const auto& p : test::permutationsOf(mats, {"dir"}, EnvironmentMode::Sh, Precision::Fp16)) perms.push_back(p);
  BuildOptions o;
  o.targets = {Target::Spirv, Target::Glsl450, Target::Hlsl, Target::Msl};
  o.jobs = 1;
  BuildStats s1, s4;
  auto one = buildPermutations(lib, perms, o, &s1);
  o.jobs = 4;
  auto four = buildPermutations(lib, perms, o, &s4);
  test::requireIdentical(one, four);
  CHECK(s1.permutations == perms.size());
  CHECK(s1.compiled == perms.size());
  CHECK(s1.uniqueSpirv == s4.uniqueSpirv);
  // Results in input order.
  for (size_t i = 0; i < perms.size(); ++i) CHECK(four[i].shader.key == perms[i].key());
}

TEST_CASE("identical emitted GLSL is compiled once; unique SPIR-V is counted", "[build]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const auto& mats = test::loadedMaterials(lib, {"ue4_metal", "filament_plastic"});
  auto perms = test::permutationsOf(mats, {"dir"}, EnvironmentMode::None);
  perms.push_back(perms[0]);  // the same permutation twice (two scene entries of one material)
  BuildStats s;
  auto built = buildPermutations(lib, perms, {}, &s);
  CHECK(s.permutations == 3);
  CHECK(s.compiled == 2);
  CHECK(s.uniqueSpirv == 2);
  CHECK(built[2].artifacts.spirv == built[0].artifacts.spirv);
  CHECK(built[2].compileMs == 0);  // reported once, on the first
  CHECK(built[0].compileMs > 0);
  CHECK(built[0].spirvHash.size() == 16);
}

TEST_CASE("fp16 permutations skip spirv-opt and still validate", "[build][fp16]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto perms = test::permutationsOf(test::loadedMaterials(lib, {"worn_car_paint"}), {"dir", "point"},
                                    EnvironmentMode::IblLut, Precision::Fp16);
  auto built = buildPermutations(lib, perms, {});
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  CHECK(tools.Validate(built[0].artifacts.spirv));
  // glslang's own output keeps OpName debug names that spirv-opt's performance passes strip.
  std::string text;
  REQUIRE(tools.Disassemble(built[0].artifacts.spirv, &text));
  CHECK(text.find("OpCapability Float16") != std::string::npos);
  CHECK(text.find("OpName") != std::string::npos);
}

TEST_CASE("every failing permutation is reported, in input order, and nothing is returned", "[build]") {
  // A library with one brick broken: every material that includes it fails.
  test::ScratchDir root("build_broken_lib");
  fs::copy(test::sourceDir() / "shaderlib", test::rootOf(root), fs::copy_options::recursive);
  ShaderLibrary lib = ShaderLibrary::load(test::rootOf(root));
  const auto& mats = test::loadedMaterials(lib, {"filament_plastic", "ue4_metal", "frostbite_dielectric"});
  auto perms = test::permutationsOf(mats, {"dir"}, EnvironmentMode::None);
  const std::string brickId = emitPermutation(lib, perms[0]).bricks.front();
  const Brick* brick = lib.findBrick(brickId);
  REQUIRE(brick);
  std::vector<size_t> using_;
  for (size_t i = 0; i < perms.size(); ++i) {
    auto bricks = emitPermutation(lib, perms[i]).bricks;
    if (std::find(bricks.begin(), bricks.end(), brickId) != bricks.end()) using_.push_back(i);
  }
  REQUIRE(using_.size() >= 2);
  {
    std::ofstream(test::rootOf(root) / brick->file, std::ios::app) << "\nfloat broken() { return undefinedSymbol; }\n";
  }
  ShaderLibrary broken = ShaderLibrary::load(test::rootOf(root));
  const auto& brokenMats = test::loadedMaterials(broken, {"filament_plastic", "ue4_metal", "frostbite_dielectric"});
  BuildOptions o;
  o.jobs = 3;
  try {
    buildPermutations(broken, test::permutationsOf(brokenMats, {"dir"}, EnvironmentMode::None), o);
    FAIL("a broken brick compiled");
  } catch (const DiagnosticError& e) {
    REQUIRE(e.diagnostics().size() == using_.size());
    for (size_t k = 0; k < using_.size(); ++k) {
      INFO(formatDiagnostic(e.diagnostics()[k]));
      CHECK(e.diagnostics()[k].code == "E-GLSL");
      CHECK(e.diagnostics()[k].where.file == ShaderLibrary::displayPath(brick->file));
    }
  }
}

TEST_CASE("a streamed build in small windows writes the same package as one window, and compiles a unit once",
          "[build][package]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  const auto& mats = test::loadedMaterials(lib, {"brushed_metal", "clearcoat_metal", "filament_plastic", "satin_sheen",
                                                 "worn_car_paint", "ue4_metal", "velvet_green"});
  ScenePlan plan;
  plan.required = test::permutationsOf(mats, {"dir", "point"}, EnvironmentMode::Sh);
  for (const auto& p : test::permutationsOf(mats, {"dir"}, EnvironmentMode::None, Precision::Fp16))
    plan.required.push_back(p);
  const test::ScratchDir dir("stream_windows");
  PackageInputs in;
  in.lib = &lib;
  in.plan = &plan;
  in.targets = {Target::Spirv, Target::Glsl450, Target::Msl};
  BuildOptions o;
  o.targets = in.targets;
  o.jobs = 2;

  BuildStats whole;
  auto built = buildPermutations(lib, plan.required, o, &whole);
  in.built = &built;
  PackageWriter buffered;
  addPackageFiles(buffered, in);
  buffered.commit(test::rootOf(dir) / "one");

  o.window = 3;  // 14 permutations: five windows, the last one short
  PackageWriter streamed;
  streamed.stage(test::rootOf(dir) / "three");
  PackageStream stream(streamed, in);
  size_t next = 0;
  BuildStats windowed;
  buildPermutationsStreaming(
      lib, plan.required, o,
      [&](size_t i, BuiltPermutation& b) {
        CHECK(i == next++);  // in input order
        CHECK(!b.artifacts.spirv.empty());
        stream.add(plan.required[i], b);
      },
      &windowed);
  stream.finish();
  streamed.commit(test::rootOf(dir) / "three");
  CHECK(next == plan.required.size());
  CHECK(windowed.compiled == whole.compiled);
  CHECK(windowed.uniqueSpirv == whole.uniqueSpirv);
  size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(test::rootOf(dir) / "one")) {
    if (!e.is_regular_file()) continue;
    ++files;
    const fs::path rel = fs::relative(e.path(), test::rootOf(dir) / "one");
    INFO(rel);
    CHECK(test::readFile(e.path()) == test::readFile(test::rootOf(dir) / "three" / rel));
  }
  // Each target's file per distinct kernel and per distinct fragment shader (docs/package.md),
  // and per permutation include/<key>.glsl and, with msl among the targets, include/<key>.metal.
  std::set<std::string> fragments;
  for (const auto& b : built) fragments.insert(b.fragmentHash);
  CHECK(files == 3 + 2 * plan.required.size() + 3 * whole.uniqueSpirv + 3 * fragments.size());

  // A permutation repeated in a later window reuses its unit: not compiled again, and it
  // carries the unit's hash, instruction count and reflection but not its code.
  std::vector<Permutation> repeated{plan.required[0], plan.required[1], plan.required[0]};
  o.window = 2;
  std::vector<BuiltPermutation> got(3);
  BuildStats s;
  buildPermutationsStreaming(
      lib, repeated, o, [&](size_t i, BuiltPermutation& b) { got[i] = b; }, &s);
  CHECK(s.compiled == 2);
  CHECK(s.units == 2);
  CHECK(got[2].artifacts.spirv.empty());
  CHECK(got[2].spirvHash == got[0].spirvHash);
  CHECK(got[2].spirvInstructions == got[0].spirvInstructions);
  CHECK(got[2].artifacts.reflection == got[0].artifacts.reflection);
  CHECK(got[2].artifacts.targets.size() == got[0].artifacts.targets.size());
  CHECK(got[2].compileMs == 0);
  // The same for its fragment shader.
  CHECK(got[2].artifacts.fragment.spirv.empty());
  CHECK(!got[2].fragmentHash.empty());
  CHECK(got[2].fragmentHash == got[0].fragmentHash);
  CHECK(got[2].fragmentInstructions == got[0].fragmentInstructions);
  CHECK(got[2].artifacts.fragment.reflection == got[0].artifacts.fragment.reflection);
  CHECK(got[2].artifacts.fragment.targets.size() == got[0].artifacts.fragment.targets.size());
}
