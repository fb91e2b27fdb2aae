// Emit: the compute kernel that integrates the DFG LUT on the GPU. It is assembled from the
// library's bricks (included with #line directives back to shaderlib/, as emit does for
// probes) plus a generated main() that follows the harness kernel contract: record i holds
// (NoV, perceptual roughness), the sample loop runs inside the shader, and the three channels
// go to mbOut[3i .. 3i+2].
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emit/emitter.hpp"
#include "library/shader_library.hpp"

namespace mb::lut {

// The bricks the kernel is built from, by role. The CPU same-sum evaluates the registered
// double references of exactly these ids (lut_reference.cpp).
struct LutBricks {
  std::string hammersley;
  std::string sampleGgx;
  std::string visibility;
  std::string clothD;
  std::string clothV;
  std::vector<std::string> all() const { return {hammersley, sampleGgx, visibility, clothD, clothV}; }
};

// The library's bricks of the kernel roles (slot.json "kernel_roles", docs/formats.md):
// hammersley, sample_ggx, dfg_visibility, cloth_dfg_d, cloth_dfg_v. Throws DiagnosticError
// (E-UNKNOWN-BRICK) when no brick takes one of them.
LutBricks lutBricks(const ShaderLibrary& lib);

// The deterministic quadrature (docs/lut.md "The quadrature kernel"; the same structure as the
// adaptive references ref::dfgIntegrals and ref::clothDfgIntegral, with fixed nodes): outer
// composite Gauss-Legendre over x = ln tan(theta_h) (GGX) or z = ln cos(theta_h) (Charlie),
// split where the azimuth range starts to shrink, in panels no wider than the width; inner
// Gauss-Legendre over the azimuth range with n.l > 0.
//
// The node counts are data: the rule below is the cheapest of the family measured by
// mb_bench_lut_rule (bench/README.md) whose error *in double* stays below 1/8 of the LUT's
// bounds (1e-4 absolute, 1e-3 relative) at every texel centre tested (16^2 and 64^2 whole, the
// first and last four rows and columns and a 32-per-axis sub-grid of 128^2 ... 4096^2). The
// other 7/8 are left for the kernel's fp32 rounding (measured: the GPU table is within 3.9e-7
// absolute and 1.3e-6 relative of the double rule at 16^2, test_lut.cpp) and margin.
struct QuadratureRule {
  // GGX where every azimuth has n.l > 0 (theta_h <= thetaFull): the integrand is analytic in
  // x, so plain Gauss-Legendre; the azimuth range is [0, pi], whose node cosines are constants.
  int ggxFullOuter = 12;
  int ggxFullInner = 6;
  // GGX where the range shrinks (phiMax = acos(kappa) has square-root ends): cosine-substituted
  // panels x = p + (q - p)(1 - cos(pi u))/2; inner nodes clustered at phiMax, where n.l -> 0
  // and V has structure of width ~alpha in n.l: phi = phiMax sin(pi u / 2).
  int ggxPartialOuter = 16;
  int ggxPartialInner = 8;
  // Charlie, both parts cosine-substituted (for alpha > 1/2, D ~ sin^(1/alpha) has an algebraic
  // singularity at theta_h = 0, the upper end), plain inner Gauss-Legendre.
  int clothOuter = 20;
  int clothInner = 4;
  double ggxBelowPeak = 8.0;     // x from ln(alpha) - 8: e^-16 of the mass below
  double ggxAbovePeak = 12.0;    // to ln(alpha) + 12: alpha^2 / t < e^-24 above
  double ggxPanelWidth = 4.0;    // both parts
  double clothBelowPeak = 10.0;  // z from ln(sqrt(alpha)) - 10: c < e^-10 sqrt(alpha)
  double clothAbovePeak = 3.0;   // to ln(sqrt(alpha)) + 3: (1 - c^2)^(1/(2 alpha)) < e^-200
  double clothPanelWidth = 3.0;
};

// The same rule evaluated in double (exact geometry, the bricks' double references' formulas):
// what mb_bench_lut_rule compares with the adaptive references to choose the node counts.
// Channels as the kernel's; `evaluations` receives the inner-node count (GGX + cloth).
std::array<double, 3> evaluateQuadratureRule(const QuadratureRule& rule, double NoV, double perceptualRoughness,
                                             long* evaluations = nullptr);

// From the library's lutBricks. Throws DiagnosticError (E-UNKNOWN-BRICK) when the library
// lacks one of the bricks.
EmittedShader emitDfgQuadratureKernel(const ShaderLibrary& lib, const QuadratureRule& rule = {});

// Filament's Hammersley estimators (the table before the quadrature; `lut --estimator
// hammersley`). Throws DiagnosticError (E-UNKNOWN-BRICK) when the library lacks one of the bricks.
EmittedShader emitDfgLutKernel(const ShaderLibrary& lib, uint32_t samples);

}  // namespace mb::lut
