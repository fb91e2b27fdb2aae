#include "lut/lut_reference.hpp"

#include <algorithm>
#include <cmath>

#include "common/cloth_dfg_reference.hpp"
#include "common/ibl_reference.hpp"
#include "core/diagnostics.hpp"

namespace mb::lut {
namespace {

using ref::Vec3;
const Vec3 kNormal{0.0, 0.0, 1.0};
constexpr double kUnitRoundoff = 0x1p-24;
// Roundings of one sample term and of the final scaling: V (two sqrt, ~12 operations), the
// products by n.l, v.h, 1/n.h and 4, pow5 (4), the scale 1/N or 8 pi/N; each builtin within
// 2 ulps. 32 covers them with margin.
constexpr double kTermRoundings = 32.0;
// pow(x, y) = exp2(y log2 x) in D_Charlie, x = |n x h|^2, y = 1/(2 alpha): the rounding of
// log2 x, of the product by y and of alpha = r^2 each move the result by ~|z| ln 2 ulps,
// z = y log2 x; and pow's condition number in x is y, so the rounding x itself carries
// (normalize in makeGeometry, cross, dot: <= 8 ulps) becomes 8 y ulps of D. At the
// smallest texel-centre roughness of a 128 table y = 32768: a 1.6% bound on those terms.
constexpr double kPowExponentUlps = 6.0;
constexpr double kPowBaseUlps = 8.0;
// Smallest normal fp32 value: a product that falls below it may flush to zero (Vulkan allows
// denormals to flush), an absolute error of up to 2^-126 times the factors applied after it.
constexpr double kFp32MinNormal = 0x1p-126;

const ref::Reference* requireReference(const std::string& id) {
  const ref::Reference* r = ref::Registry::references().find(id);
  if (!r) {
    throw DiagnosticError({{Severity::Error,
                            "E-NO-REFERENCE",
                            {"shaderlib/manifest.json", 0, 0},
                            "brick '" + id + "' has no registered C++ reference",
                            ""}});
  }
  return r;
}

// A brick reference of signature (Geometry, float) at (n, v, l, alpha).
double evalGeometryAlpha(const ref::Reference& r, const Vec3& v, const Vec3& l, double alpha) {
  const double in[10] = {kNormal.x, kNormal.y, kNormal.z, v.x, v.y, v.z, l.x, l.y, l.z, alpha};
  double out = 0;
  r.eval(in, &out);
  return out;
}

Vec3 reflect(const Vec3& v, const Vec3& h) { return 2.0 * ref::dot(v, h) * h - v; }

// Two unit vectors orthogonal to h (and to each other).
std::array<Vec3, 2> tangents(const Vec3& h) {
  Vec3 a = std::fabs(h.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  Vec3 t = ref::normalize(ref::cross(h, a));
  return {t, ref::cross(h, t)};
}

}  // namespace

struct SameSum::Terms {
  std::array<double, kChannels> t{};
  // Rounding multiplier of the cloth term's pow (D_Charlie) beyond the plain arithmetic.
  double powUlps = 0;
};

SameSum::SameSum(const LutBricks& b)
    : hammersley_(requireReference(b.hammersley)),
      sampleGgx_(requireReference(b.sampleGgx)),
      visibility_(requireReference(b.visibility)),
      clothD_(requireReference(b.clothD)),
      clothV_(requireReference(b.clothV)) {}

// One sample's terms, exactly as the kernel's loop body forms them.
SameSum::Terms SameSum::terms(const Vec3& v, const Vec3& hGgx, const Vec3& hUniform, double alpha) const {
  Terms out;
  Vec3 l = reflect(v, hGgx);
  ref::Geometry g = ref::makeGeometry(kNormal, v, l);
  if (g.NoL > 0.0) {
    double Gv = 4.0 * evalGeometryAlpha(*visibility_, v, l, alpha) * g.NoL * g.VoH / g.NoH;
    out.t[kChannelGvFc] = Gv * std::pow(1.0 - g.VoH, 5.0);
    out.t[kChannelGv] = Gv;
  }
  Vec3 lc = reflect(v, hUniform);
  ref::Geometry c = ref::makeGeometry(kNormal, v, lc);
  if (c.NoL > 0.0) {
    double D = evalGeometryAlpha(*clothD_, v, lc, alpha);
    out.t[kChannelCloth] = evalGeometryAlpha(*clothV_, v, lc, alpha) * D * c.NoL * c.VoH;
    Vec3 nxh = ref::cross(c.n, c.h);
    double sin2 = ref::dot(nxh, nxh);
    const double y = 0.5 / alpha, z = sin2 > 0.0 ? std::fabs(y * std::log2(sin2)) : 0.0;
    out.powUlps = kPowExponentUlps * z + kPowBaseUlps * y;
  }
  return out;
}

TexelSum SameSum::evaluate(float NoVf, float roughnessf, uint32_t samples) const {
  const double NoV = NoVf, r = roughnessf, alpha = r * r;
  const double sinV = std::sqrt(std::max(0.0, 1.0 - NoV * NoV));
  const Vec3 v{sinV, 0.0, NoV};
  // v turned towards and away from n by kViewDirectionError.
  const Vec3 vTilt{NoV, 0.0, -sinV};
  const Vec3 vMoved[2] = {ref::normalize(v + vTilt * kViewDirectionError),
                          ref::normalize(v - vTilt * kViewDirectionError)};

  std::array<double, kChannels> sum{}, absSum{}, directional{}, arithmetic{};
  std::array<std::array<double, kChannels>, 2> sumMoved{};
  for (uint32_t s = 0; s < samples; ++s) {
    const double u1 = static_cast<double>(s) / samples;
    double u2 = 0;
    const double index = s;
    hammersley_->eval(&index, &u2);
    // importance_sample_ggx(Geometry(n, v, n), u1, u2, alpha): only the frame's n matters.
    const double sampleIn[12] = {0, 0, 1, v.x, v.y, v.z, 0, 0, 1, u1, u2, alpha};
    double hOut[3];
    sampleGgx_->eval(sampleIn, hOut);
    const Vec3 hGgx{hOut[0], hOut[1], hOut[2]};
    const double phi = 2.0 * ref::kPi * u1, sinTheta = std::sqrt(u2 * (2.0 - u2));
    const Vec3 hUniform{sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0 - u2};

    Terms base = terms(v, hGgx, hUniform, alpha);
    // Sensitivity to the sample direction: both half vectors moved along their two tangents.
    std::array<double, kChannels> moved2{};
    auto tg = tangents(hGgx), tu = tangents(hUniform);
    for (int k = 0; k < 2; ++k) {
      Terms m = terms(v, ref::normalize(hGgx + tg[k] * kSampleDirectionError),
                      ref::normalize(hUniform + tu[k] * kSampleDirectionError), alpha);
      for (uint32_t c = 0; c < kChannels; ++c) moved2[c] += (m.t[c] - base.t[c]) * (m.t[c] - base.t[c]);
    }
    for (int k = 0; k < 2; ++k) {
      Terms m = terms(vMoved[k], hGgx, hUniform, alpha);
      for (uint32_t c = 0; c < kChannels; ++c) sumMoved[k][c] += m.t[c];
    }
    for (uint32_t c = 0; c < kChannels; ++c) {
      double a = std::fabs(base.t[c]);
      sum[c] += base.t[c];
      absSum[c] += a;
      directional[c] += std::sqrt(moved2[c]);
      double roundings = kTermRoundings + (c == kChannelCloth ? base.powUlps : 0.0);
      arithmetic[c] += roundings * kUnitRoundoff * a;
    }
  }
  const double scale[kChannels] = {1.0 / samples, 1.0 / samples, 8.0 * ref::kPi / samples};
  // Underflow: the largest factors that can follow a flushed intermediate in one term are
  // Gv's 4 V <= 2 / (alpha n.v) (V's n.l = 0 limit) and the cloth term's D coefficient
  // (2 + 1/alpha) / (2 pi) times V_Ashikhmin <= 1 / (4 n.v).
  const double NoVClamped = std::max(NoV, ref::kMinNoV);
  const double largestFactor[kChannels] = {2.0 / (alpha * NoVClamped), 2.0 / (alpha * NoVClamped),
                                           (2.0 + 1.0 / alpha) / (2.0 * ref::kPi) / (4.0 * NoVClamped)};
  TexelSum out;
  for (uint32_t c = 0; c < kChannels; ++c) {
    double view = std::max(std::fabs(sumMoved[0][c] - sum[c]), std::fabs(sumMoved[1][c] - sum[c]));
    // Recursive summation of N terms: |error| <= (N - 1) u Sum|t| (Higham 2002, eq. 4.4).
    double summation = (samples - 1.0) * kUnitRoundoff * absSum[c];
    double underflow = samples * kTermRoundings * kFp32MinNormal * largestFactor[c];
    out.value[c] = scale[c] * sum[c];
    out.bound[c] = scale[c] * (summation + arithmetic[c] + directional[c] + view + underflow);
  }
  return out;
}

std::array<double, kChannels> quadrature(double NoV, double perceptualRoughness) {
  double alpha = perceptualRoughness * perceptualRoughness;
  ref::DfgIntegrals d = ref::dfgIntegrals(NoV, alpha);
  std::array<double, kChannels> out{};
  out[kChannelGvFc] = d.gvFc;
  out[kChannelGv] = d.gv;
  out[kChannelCloth] = ref::clothDfgIntegral(NoV, alpha);
  return out;
}

}  // namespace mb::lut
