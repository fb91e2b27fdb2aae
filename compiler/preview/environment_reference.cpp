#include "preview/environment_reference.hpp"

#include <cmath>
#include <numbers>

#include "preview/dir_math.hpp"
#include "preview/environment_radiance.hpp"

namespace mb::preview {
namespace {

using V3 = std::array<double, 3>;

// Van der Corput radical inverse in base 2: the bits of k reversed, over 2^32.
double radicalInverse(uint32_t b) {
  b = (b << 16) | (b >> 16);
  b = ((b & 0x00ff00ffu) << 8) | ((b & 0xff00ff00u) >> 8);
  b = ((b & 0x0f0f0f0fu) << 4) | ((b & 0xf0f0f0f0u) >> 4);
  b = ((b & 0x33333333u) << 2) | ((b & 0xccccccccu) >> 2);
  b = ((b & 0x55555555u) << 1) | ((b & 0xaaaaaaaau) >> 1);
  return b * 0x1p-32;
}

}  // namespace

std::array<double, 3> prefilterReference(const std::string& environment, const std::array<double, 3>& n, double alpha,
                                         uint32_t samples, uint32_t peakSamples) {
  const V3 up = std::abs(n[2]) < 0.999 ? V3{0, 0, 1} : V3{1, 0, 0};
  const V3 tx = normalized(cross(up, n)), ty = cross(n, tx);
  V3 sum{};
  double weight = 0;
  for (uint32_t k = 0; k < samples; ++k) {
    const double u1 = double(k) / samples, u2 = radicalInverse(k);
    const double cosT = std::sqrt((1 - u2) / (1 + (alpha * alpha - 1) * u2)), sinT = std::sqrt(1 - cosT * cosT);
    const double phi = 2 * std::numbers::pi * u1;
    V3 h;
    for (int c = 0; c < 3; ++c) h[c] = tx[c] * sinT * std::cos(phi) + ty[c] * sinT * std::sin(phi) + n[c] * cosT;
    const double NoH = dot(n, h);
    V3 l;
    for (int c = 0; c < 3; ++c) l[c] = 2 * NoH * h[c] - n[c];
    const double NoL = dot(n, l);
    if (NoL <= 0) continue;
    const Rgb L = environmentSmoothRadiance(environment, normalized(l));
    for (int c = 0; c < 3; ++c) sum[c] += L[c] * NoL;
    weight += NoL;
  }
  if (const PeakCone* cone = environmentPeak(environment)) {
    const double a2 = alpha * alpha;
    for (uint32_t k = 0; k < peakSamples; ++k) {
      const double x = radicalInverse(k) * cone->oneMinusCosMax, cosT = 1 - x, sinT = std::sqrt(x * (2 - x));
      const double phi = 2 * std::numbers::pi * k / peakSamples;
      V3 l;
      for (int c = 0; c < 3; ++c)
        l[c] = cone->axis[c] * cosT + (cone->u[c] * std::cos(phi) + cone->v[c] * std::sin(phi)) * sinT;
      const double NoL = dot(n, l);
      if (NoL <= 0) continue;
      const V3 h = normalized({n[0] + l[0], n[1] + l[1], n[2] + l[2]});
      const double NoH = dot(n, h), t = NoH * NoH * (a2 - 1) + 1;
      const double D = a2 / (std::numbers::pi * t * t);  // GGX (Walter et al. 2007 eq. 33)
      // Uniform in the cone's solid angle 2 pi (1 - cos max); the lobe sum is over `samples`.
      const double scale = NoL * 0.25 * D * 2 * std::numbers::pi * cone->oneMinusCosMax * samples / peakSamples;
      const Rgb L = environmentPeakRadiance(environment, l);
      for (int c = 0; c < 3; ++c) sum[c] += L[c] * scale;
    }
  }
  for (auto& c : sum) c /= weight;
  return sum;
}

}  // namespace mb::preview
