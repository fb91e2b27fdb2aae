// docs/bricks.md: the brick catalogue per slot, with each brick's signature, citation,
// domain, tolerance and the error measured on the GPU, plus the worst fp32 error of each
// slot before and after the stability fixes (naive variants substituted).
#pragma once
#include <string>

#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"

namespace mb {

struct CatalogueOptions {
  uint64_t samples = 4096;
  uint64_t seed = 1;
};

std::string brickCatalogueMarkdown(const ShaderLibrary& lib, harness::VulkanHarness& gpu,
                                   const CatalogueOptions& options = {});

}  // namespace mb
