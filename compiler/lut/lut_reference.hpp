// The CPU side of the LUT check: the kernel's Monte-Carlo sum evaluated in double from the
// bricks' registered references (never by compiling the GLSL as C++), together with a
// derived bound on how far an fp32 evaluation of the same sum may be from it; and the
// deterministic quadrature of the exact integrals (the ground truth the finite sum
// estimates).
#pragma once
#include <array>
#include <cstdint>

#include "common/reference.hpp"
#include "lut/dfg_lut.hpp"
#include "lut/lut_kernel.hpp"

namespace mb::lut {

struct TexelSum {
  std::array<double, kChannels> value{};
  // |fp32 kernel - value| <= bound (docs/lut.md "fp32 bound"): the summation bound
  // (N - 1) u Sum|t|, per-term arithmetic (32 + 6 |z| + 8 y) u |t| (y, z: the cloth pow's
  // exponent and exp2 argument, lut_reference.cpp), and the measured
  // sensitivity of every term to the sample direction (kSampleDirectionError) and of the
  // whole sum to the view direction (kViewDirectionError), and fp32 underflow of a term's
  // intermediate (2^-126 times the factors that follow it).
  std::array<double, kChannels> bound{};
};

// Direction error of an fp32 sample half vector: importance_sample_ggx's manifest bound
// (1e-6 per component, <= 1.7e-6 in length), plus u1 = s/N rounded by the division (<= 2.5
// ulp of u1: 2 pi x 1.5e-7 = 9.4e-7 rad in phi), plus the reflection l = 2 (v.h) h - v and
// makeGeometry's normalize and half vector (a few ulps, < 3e-7): < 3e-6, taken as 4e-6.
inline constexpr double kSampleDirectionError = 4e-6;
// fp32 v = (sqrt(1 - NoV^2), 0, NoV) and its normalize: two roundings per component, 4 ulps.
inline constexpr double kViewDirectionError = 0x1p-21;

class SameSum {
 public:
  // Throws DiagnosticError (E-NO-REFERENCE) when a brick has no registered reference.
  explicit SameSum(const LutBricks& bricks);
  // The kernel's sum for the fp32 record (NoV, perceptual roughness) with `samples` points.
  TexelSum evaluate(float NoV, float perceptualRoughness, uint32_t samples) const;

 private:
  struct Terms;
  Terms terms(const ref::Vec3& v, const ref::Vec3& hGgx, const ref::Vec3& hUniform, double alpha) const;
  const ref::Reference* hammersley_;
  const ref::Reference* sampleGgx_;
  const ref::Reference* visibility_;
  const ref::Reference* clothD_;
  const ref::Reference* clothV_;
};

// The exact integrals at (NoV, perceptual roughness): channels 0 and 1 by ref::dfgIntegrals
// (common/ibl_reference.hpp), channel 2 by ref::clothDfgIntegral
// (common/cloth_dfg_reference.hpp).
std::array<double, kChannels> quadrature(double NoV, double perceptualRoughness);

}  // namespace mb::lut
