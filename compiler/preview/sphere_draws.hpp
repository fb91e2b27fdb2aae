// What the preview's two passes draw (docs/preview.md), whatever language the shaders are in:
// the sphere mesh once per tile, each draw with its blocks (the vertex stage's matrices, the
// frame block, the sphere's material parameters) and the environment's textures. The SPIR-V
// target draws it with Vulkan, the GL-family targets by name (draw_passes.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/environment_mode.hpp"
#include "harness/vulkan_graphics.hpp"
#include "load/material_desc.hpp"
#include "preview/preview.hpp"
#include "preview/preview_scene.hpp"

namespace mb::preview {

// Per sphere: every non-constant parameter's value (its default, or the sweep's step).
using SphereParams = std::map<std::string, std::vector<double>>;

struct SphereDraws {
  uint32_t width = 0, height = 0, tile = 0;
  harness::Mesh mesh;
  // engine_vertex.vert's MbVertexPush: model (object -> world), then viewProjection, column-major.
  std::vector<uint8_t> vertexBlock;
  std::vector<uint8_t> frame;                // MbFrameBlock (std140)
  std::vector<std::vector<uint8_t>> params;  // MbMaterialParams per sphere (std140; empty: none)
  // Which of the environment's textures the fragment shader samples.
  bool prefiltered = false, dfg = false, ltc = false;
};

SphereDraws sphereDraws(const PreviewOptions& o, const MaterialDesc& m, const std::vector<SphereParams>& spheres,
                        const std::vector<PreviewLight>& lights, EnvironmentMode environmentMode,
                        const EnvironmentMaps& environment);

}  // namespace mb::preview
