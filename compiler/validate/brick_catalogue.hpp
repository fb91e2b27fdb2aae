// docs/bricks.md: the brick catalogue per slot, with each brick's signature, citation,
// domain, tolerance and the error measured on the GPU, plus the worst fp32 error of each
// slot before and after the stability fixes (naive variants substituted).
//
// The measured figures are kept apart from the rest (CatalogueFigures, as the text the file
// prints), so that the catalogue can be regenerated without a GPU: the parts that need none
// come from the library, and the figures are carried over from the previous file for the bricks
// it measured (carriedCatalogueFigures); a brick it lacks shows "not measured", and the file
// says so until a run with a GPU measures it.
#pragma once
#include <map>
#include <string>

#include "harness/vulkan_harness.hpp"
#include "library/shader_library.hpp"

namespace mb {

struct CatalogueOptions {
  uint64_t samples = 4096;
  uint64_t seed = 1;
};

// What the GPU measured, as the catalogue prints it (absent: not measured).
struct CatalogueFigures {
  std::string device;                             // the header's "on <device>"
  std::map<std::string, std::string> slotCells;   // slot -> its summary row's measured cells
  std::map<std::string, std::string> brickCells;  // brick id -> "max abs | max rel[ (FAILS)]"
  std::map<std::string, std::string> naiveRel;    // brick id -> its naive form's measured max rel
};

// Validates every brick (and naive form) on `gpu`.
CatalogueFigures measureCatalogueFigures(const ShaderLibrary& lib, harness::VulkanHarness& gpu,
                                         const CatalogueOptions& options = {});
// The figures `previous` (an earlier catalogue's text) printed for the bricks of `lib` it lists;
// a slot's summary only when it listed every brick of the slot.
CatalogueFigures carriedCatalogueFigures(const ShaderLibrary& lib, const std::string& previous);

std::string brickCatalogueMarkdown(const ShaderLibrary& lib, const CatalogueFigures& figures,
                                   const CatalogueOptions& options = {});
// Measures, then renders.
std::string brickCatalogueMarkdown(const ShaderLibrary& lib, harness::VulkanHarness& gpu,
                                   const CatalogueOptions& options = {});

}  // namespace mb
