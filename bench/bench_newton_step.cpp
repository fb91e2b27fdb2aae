// The numbers behind max_noh_decima_newton's tolerance (shaderlib/sphere_max_noh/slot.json,
// docs/validation.md; issue 14 item 4), in long double over the brick's domain
// (n.v in [1e-3, 1], n.l in [0, 1], sin a in [0, 0.95], uniform as the validator's strata):
//   kappa = (|(p - s)^2| + |q N0 VoTr / 2| + |q NoTr D0|) / |xDenom|, the cancellation left in
//           the regrouped Newton denominator;
//   S     = |d(n.h)/d ln x| at the step x = tan(theta/2) = xNum / xDenom (central difference),
//           how far n.h moves per unit relative error of x.
// The step's fp32 arithmetic moves n.h by <= S (c0 + c1 kappa) u; the tolerance takes the
// maxima of S and kappa S where kappa <= 10 and leaves kappa > 10 (the second derivative along
// the rim vanishing) to the input-conditioning allowance. Prints JSON.
// Usage: mb_bench_newton_step [samples] [seed]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>

namespace {

using R = long double;
struct V3 {
  R x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, R s) { return {a.x * s, a.y * s, a.z * s}; }
R dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 normalize(V3 a) { return a * (1 / std::sqrt(dot(a, a))); }

// The brick's step (max_noh_decima_newton.glsl) in long double, with x scaled by xScale.
struct Step {
  bool onRim = false;  // false: the mirror ray hits the sphere (n.h = 1, no step)
  R kappa = 0, x = 0, noh = 0;
};
Step step(V3 n, V3 v, V3 l, R sinA, R xScale) {
  Step s;
  V3 r = n * (2 * dot(n, v)) - v;
  R RoL = dot(r, l);
  V3 rxl = cross(r, l);
  R sin2RL = dot(rxl, rxl);
  if (RoL > 0 && sin2RL <= sinA * sinA) return s;
  s.onRim = true;
  R cosA = std::sqrt(1 - sinA * sinA), rInv = sinA / std::sqrt(sin2RL);
  V3 tr = (r - l * RoL) * rInv, br = rxl * (dot(n, rxl) < 0 ? -rInv : rInv);
  V3 w = v + l * cosA + tr;
  R N0 = dot(n, w), D0 = dot(w, w) / 2, q = N0 * D0;
  R NoTr = dot(n, tr), VoTr = dot(v, tr), NoBr = dot(n, br), VoBr = dot(v, br);
  R pMinusS = NoBr * D0 - VoBr * N0;
  R xNum = q * (-NoBr * D0 / 2 + VoBr * N0 / 4);
  R a = pMinusS * pMinusS, b = q * N0 * VoTr / 2, c = q * NoTr * D0;
  s.kappa = (std::fabs(a) + std::fabs(b) + std::fabs(c)) / std::fabs(a + b - c);
  s.x = xNum / (a + b - c) * xScale;
  R sinT = 2 * s.x / (1 + s.x * s.x), cosT = (1 - s.x * s.x) / (1 + s.x * s.x);
  s.noh = dot(n, normalize(v + l * cosA + tr * cosT + br * sinT));
  return s;
}

V3 fromAngles(double cosTheta, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

}  // namespace

int main(int argc, char** argv) {
  long samples = argc > 1 ? std::atol(argv[1]) : 1000000;
  unsigned long seed = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 7;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double kappaSplit = 10.0, twoPi = 2.0 * std::numbers::pi;
  long onRim = 0, wellConditioned = 0;
  double maxS = 0, maxKappaSWell = 0, maxKappaSAll = 0, maxKappa = 0;
  for (long i = 0; i < samples; ++i) {
    V3 n{0, 0, 1}, v = fromAngles(1e-3 + (1 - 1e-3) * U(rng), twoPi * U(rng));
    V3 l = fromAngles(U(rng), twoPi * U(rng));
    R sinA = 0.95 * U(rng);
    Step s = step(n, v, l, sinA, 1);
    if (!s.onRim || s.x == 0) continue;
    ++onRim;
    const R h = 1e-7L;
    R S = std::fabs((step(n, v, l, sinA, 1 + h).noh - step(n, v, l, sinA, 1 - h).noh) / (2 * h));
    double kS = static_cast<double>(s.kappa * S);
    maxS = std::max(maxS, static_cast<double>(S));
    maxKappa = std::max(maxKappa, static_cast<double>(s.kappa));
    maxKappaSAll = std::max(maxKappaSAll, kS);
    if (s.kappa <= kappaSplit) ++wellConditioned, maxKappaSWell = std::max(maxKappaSWell, kS);
  }
  std::printf(
      "{\"samples\": %ld, \"seed\": %lu, \"on_rim\": %ld, \"kappa_le_10\": %ld, \"max_S\": %.4g, "
      "\"max_kappa_S_where_kappa_le_10\": %.4g, \"max_kappa_S\": %.4g, \"max_kappa\": %.4g}\n",
      samples, seed, onRim, wellConditioned, maxS, maxKappaSWell, maxKappaSAll, maxKappa);
  return 0;
}
