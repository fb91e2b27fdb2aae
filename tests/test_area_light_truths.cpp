// The area-light ground truths (issue 14, item 5): lights::sphereEffectiveD and the lobe
// integrals of common/area_light_truth.hpp against an independent brute-force integral over
// the sphere's cap (polar coordinates about the cap's centre, not about the mirror ray), in
// particular with the mirror ray through the centre, where sphereEffectiveD was 1.003x to
// 4.8x too large (its frame was built from rounding noise, docs/models/lights.md).
#include <catch2/catch.hpp>

#include <random>

#include "common/area_light_truth.hpp"

using namespace mb::ref;

namespace {

// Int_cap f(l) dw by a tensor grid about the centre c = g.l: Gauss-Legendre in the polar
// angle (panels x 8 nodes), midpoints in azimuth. Slow and simple; fine for alpha >= 0.05.
template <class F>
double bruteCap(const Geometry& g, double sinAlpha, F f, int panels = 64, int azimuths = 256) {
  static const detail_ibl::GaussLegendre<8> gl;
  lights::Frame frame = lights::frameAround(g.l);
  double a = std::asin(sinAlpha), sum = 0;
  for (int i = 0; i < panels; ++i)
    for (int k = 0; k < 8; ++k) {
      double t = a * (i + 0.5 + 0.5 * gl.x[k]) / panels, wt = 0.5 * gl.w[k] * a / panels * std::sin(t);
      for (int j = 0; j < azimuths; ++j) {
        double phi = 2 * kPi * (j + 0.5) / azimuths;
        sum += wt * (2 * kPi / azimuths) * f(lights::onCone(g.l, frame, std::cos(t), std::sin(t), phi));
      }
    }
  return sum;
}

// A view, and a light centre on its mirror ray as a caller computes it: the direction of a
// light position along the ray, so that it agrees with reflect(-v, n) only to rounding.
Geometry mirrorThroughCentre(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double theta = 1.3 * u(rng), phi = 2 * kPi * u(rng);
  Vec3 n{0, 0, 1}, v{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  Vec3 r = n * (2 * dot(n, v)) - v;
  return makeGeometry(n, v, r * (1 + 9 * u(rng)));
}

}  // namespace

TEST_CASE("sphereEffectiveD with the mirror ray through the centre agrees with a brute-force cap integral",
          "[references][area-lights]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 24; ++i) {
    Geometry g = mirrorThroughCentre(rng);
    double alpha = 0.05 + 0.5 * u(rng), sinAlpha = 0.05 + 0.5 * u(rng);
    auto D = [&](const Vec3& l) { return lights::ggxD(std::max(0.0, lights::nohFor(g, l)), alpha); };
    double brute = bruteCap(g, sinAlpha, D) / (kPi * sinAlpha * sinAlpha);
    worst = std::max(worst, std::fabs(lights::sphereEffectiveD(g, alpha, sinAlpha) / brute - 1));
  }
  INFO("worst relative difference " << worst << " (before the fix: up to 3.8, i.e. 4.8x)");
  CHECK(worst < 1e-5);
}

TEST_CASE("the sphere's lobe integrals agree with independent integrals over the cap", "[references][area-lights]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worstSpecular = 0, worstDiffuse = 0;
  for (int i = 0; i < 24; ++i) {
    // Half with the mirror ray through the centre, half with a centre anywhere, crossing the
    // horizon too (the diffuse against the closed-form-in-azimuth irradiance).
    Geometry g = mirrorThroughCentre(rng);
    if (i % 2) {
      double theta = 1.7 * u(rng), phi = 2 * kPi * u(rng);
      g = makeGeometry(g.n, g.v,
                       Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
    }
    double alpha = 0.05 + 0.5 * u(rng), sinAlpha = 0.05 + 0.5 * u(rng);
    arealights::LobeIntegrals lobe = arealights::sphereLobe(g, alpha, sinAlpha);
    double spec = bruteCap(g, sinAlpha, [&](const Vec3& l) { return arealights::specularAt(g, alpha, l); });
    if (spec > 1e-6) worstSpecular = std::max(worstSpecular, std::fabs(lobe.specular / spec - 1));
    double irradiance = lights::sphereIrradianceOverPoint(g, sinAlpha) * kPi * sinAlpha * sinAlpha;
    worstDiffuse = std::max(worstDiffuse, std::fabs(lobe.diffuse - irradiance) / (kPi * sinAlpha * sinAlpha));
  }
  INFO("worst: specular " << worstSpecular << " relative, diffuse " << worstDiffuse << " of pi sin^2 a");
  CHECK(worstSpecular < 1e-4);
  // The horizon's kink in (n.l)+ falls inside a Gauss-Legendre panel of capIntegral (graded
  // for the specular peak, not for the horizon): ~1e-6 of pi sin^2 a (measured 1.1e-6), far
  // below the representative-point errors the truth is used to measure (>= 1e-2).
  CHECK(worstDiffuse < 1e-5);
}
