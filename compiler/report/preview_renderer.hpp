// The report's previews (preview_section.hpp) drawn by `matbricks preview`'s renderer
// (preview/preview.hpp): per material one sphere per environment, GPU render, CPU reference
// and difference heatmap, with the measured error against the permutation's tolerance.
#pragma once
#include <string>
#include <vector>

#include "library/shader_library.hpp"
#include "report/preview_section.hpp"

namespace mb::report {

// Environments are built on first use and shared by every material. A material the preview
// cannot draw (a textured glTF material) gets the reason as its text and no images.
PreviewRenderer makePreviewRenderer(const ShaderLibrary& lib, std::vector<std::string> environments, uint32_t size);

}  // namespace mb::report
