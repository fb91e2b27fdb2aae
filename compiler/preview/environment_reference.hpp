// The prefilter kernel's estimator in double (tests and mb_bench_environment): written from
// Karis 2013 (PrefilterEnvMap with ImportanceSampleGGX and Hammersley), independently of the
// GLSL bricks, with the double radiance of environment_radiance.hpp.
#pragma once
#include <array>
#include <cstdint>
#include <string>

namespace mb::preview {

// Hammersley point k of `samples`: (k / samples, radical inverse of the 32-bit k);
// phi = 2 pi u1, cos^2 theta = (1 - u2) / (1 + (alpha^2 - 1) u2), in the tangent frame of
// UE4's listing (up = |n.z| < 0.999 ? z : x); returns sum L(l) n.l / sum n.l over the samples
// with n.l > 0, at unit n = v, L the smooth radiance; plus, where the environment has a peak,
// its integral Int L_peak n.l D(h)/4 dl from `peakSamples` Hammersley points uniform over the
// peak's cone, added to the numerator as the kernel does (environment_prefilter.hpp).
std::array<double, 3> prefilterReference(const std::string& environment, const std::array<double, 3>& n, double alpha,
                                         uint32_t samples, uint32_t peakSamples);

}  // namespace mb::preview
