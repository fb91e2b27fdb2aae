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

// The deterministic quadrature (docs/lut.md "The quadrature kernel"; the same structure as the
// adaptive references ref::dfgIntegrals and ref::clothDfgIntegral, with fixed nodes):
// outer composite Gauss-Legendre over x = ln tan(theta_h) (GGX) or z = ln cos(theta_h)
// (Charlie), cut where the azimuth range starts to shrink, in panels no wider than the
// width, each after the cosine substitution; inner Gauss-Legendre over the azimuth range
// with n.l > 0. The constants were chosen by measuring the double-precision rule against the
// adaptive references over the texel centres of 16^2 .. 1024^2 tables (docs/lut.md).
inline constexpr int kQuadratureOuterNodes = 16;
inline constexpr int kQuadratureInnerNodes = 8;
inline constexpr double kGgxBelowPeak = 8.0;   // x from ln(alpha) - 8: e^-16 of the mass below
inline constexpr double kGgxAbovePeak = 12.0;  // to ln(alpha) + 12: alpha^2 / t < e^-24 above
inline constexpr double kGgxPanelWidth = 4.0;
inline constexpr double kClothBelowPeak = 10.0;  // z from ln(sqrt(alpha)) - 10: c < e^-10 sqrt(alpha)
inline constexpr double kClothAbovePeak = 3.0;   // to ln(sqrt(alpha)) + 3: (1 - c^2)^(1/(2 alpha)) < e^-200
inline constexpr double kClothPanelWidth = 2.0;

// Throws DiagnosticError (E-UNKNOWN-BRICK) when the library lacks one of the bricks.
EmittedShader emitDfgQuadratureKernel(const ShaderLibrary& lib, const LutBricks& bricks = {});

// Filament's Hammersley estimators (the table before the quadrature; `lut --estimator
// hammersley`). Throws DiagnosticError (E-UNKNOWN-BRICK) when the library lacks one of the bricks.
EmittedShader emitDfgLutKernel(const ShaderLibrary& lib, uint32_t samples, const LutBricks& bricks = {});

}  // namespace mb::lut
