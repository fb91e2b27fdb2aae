// Emit: the compute kernel that integrates the DFG LUT on the GPU. It is assembled from the
// library's bricks (included with #line directives back to shaderlib/, as emit does for
// probes) plus a generated main() that follows the harness kernel contract: record i holds
// (NoV, perceptual roughness), the sample loop runs inside the shader, and the three channels
// go to mbOut[3i .. 3i+2].
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "emit/emitter.hpp"
#include "library/shader_library.hpp"

namespace mb::lut {

// The bricks the kernel is built from, by role. The CPU same-sum evaluates the registered
// double references of exactly these ids (lut_reference.cpp).
struct LutBricks {
  std::string hammersley = "hammersley_bitreverse";
  std::string sampleGgx = "importance_sample_ggx";
  std::string visibility = "v_smith_ggx_correlated";
  std::string clothD = "d_charlie";
  std::string clothV = "v_ashikhmin";
  std::vector<std::string> all() const { return {hammersley, sampleGgx, visibility, clothD, clothV}; }
};

// Throws DiagnosticError (E-UNKNOWN-BRICK) when the library lacks one of the bricks.
EmittedShader emitDfgLutKernel(const ShaderLibrary& lib, uint32_t samples, const LutBricks& bricks = {});

}  // namespace mb::lut
