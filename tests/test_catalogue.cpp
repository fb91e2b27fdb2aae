// docs/bricks.md is generated; this fails when the committed file no longer matches the
// library (regenerate with `build/bin/matbricks bricks --markdown -o docs/bricks.md`, or without
// a GPU for the parts that need none: `... --no-gpu`).
#include <catch2/catch.hpp>

#include <sstream>

#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/brick_catalogue.hpp"

using namespace mb;

TEST_CASE("the committed docs/bricks.md is current", "[catalogue][vulkan]") {
  harness::VulkanHarness gpu(harness::testDeviceOptions());
  std::string generated = brickCatalogueMarkdown(test::shippedLibrary(), gpu);
  std::string committed = test::readFile(test::sourceDir() / "docs/bricks.md");
  INFO("regenerate with: build/bin/matbricks bricks --markdown -o docs/bricks.md");
  CHECK(generated == committed);
  CHECK(gpu.validationMessages().empty());
}

TEST_CASE("docs/bricks.md's parts that need no GPU are current: regenerated without one, it is unchanged",
          "[catalogue]") {
  std::string committed = test::readFile(test::sourceDir() / "docs/bricks.md");
  const ShaderLibrary& lib = test::shippedLibrary();
  CatalogueFigures carried = carriedCatalogueFigures(lib, committed);
  // Every brick's and slot's figures are found again.
  CHECK(carried.brickCells.size() == lib.bricks().size());
  CHECK(carried.slotCells.size() == lib.slots().size());
  INFO("regenerate with: build/bin/matbricks bricks --markdown --no-gpu -o docs/bricks.md (or with a GPU)");
  CHECK(brickCatalogueMarkdown(lib, carried) == committed);
}

TEST_CASE("without a GPU, a brick the previous catalogue lacks shows 'not measured', and so does its slot's summary",
          "[catalogue]") {
  std::string committed = test::readFile(test::sourceDir() / "docs/bricks.md");
  const ShaderLibrary& lib = test::shippedLibrary();
  // The previous file without d_beckmann's row: as if the brick were new.
  std::string previous;
  std::istringstream in(committed);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("| `d_beckmann` ", 0) != 0) previous += line + "\n";
  std::string md = brickCatalogueMarkdown(lib, carriedCatalogueFigures(lib, previous));
  CHECK_THAT(md, Catch::Matchers::Contains("**Not measured yet** (regenerated without a GPU, `bricks --markdown "
                                           "--no-gpu`): `d_beckmann`."));
  CHECK_THAT(md, Catch::Matchers::Contains("| 1e-06 / 0.0005 | not measured | not measured | "));
  CHECK_THAT(md, Catch::Matchers::Contains("| `specular_d` | 4 | not measured | not measured | not measured | "
                                           "not measured | not measured | not measured | `d_ggx`"));
  // The other slots keep their figures.
  CHECK_THAT(md,
             Catch::Matchers::Contains("| `roughness` | 4 | 0.55 | 0.55 | 0 | 0 | 3.3e-07 | 3.3e-07 | none needed |"));
  // No previous file: nothing measured, every part that needs no GPU still there.
  std::string bare = brickCatalogueMarkdown(lib, carriedCatalogueFigures(lib, ""));
  CHECK_THAT(bare, Catch::Matchers::Contains("on no device: fp32"));
  CHECK_THAT(bare, Catch::Matchers::Contains("`float mb_d_beckmann(Geometry g, float alpha)`"));
}
