// docs/bricks.md is generated; this fails when the committed file no longer matches the
// library (regenerate with `build/bin/matbricks bricks --markdown -o docs/bricks.md`).
#include <catch2/catch.hpp>

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
