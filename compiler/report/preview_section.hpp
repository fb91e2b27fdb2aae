// The previews of a material in the report: the images a PreviewRenderer returns (GPU render,
// CPU reference, difference; `matbricks preview`), shown in the material's section. The report
// takes the renderer as a function so that it runs wherever preview rendering is available
// and says so plainly where it is not.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "harness/vulkan_harness.hpp"
#include "load/material_desc.hpp"

namespace mb::report {

struct PreviewImage {
  std::string caption;  // "GPU", "reference", "difference"
  std::string png;      // encoded bytes
};

struct PreviewSet {
  std::vector<PreviewImage> images;
  std::string text;     // what was rendered and its measured error, or why nothing was
  bool failed = false;  // a GPU pixel outside the permutation's tolerance of the reference
};

using PreviewRenderer = std::function<PreviewSet(const MaterialDesc&, harness::VulkanHarness&)>;

}  // namespace mb::report
