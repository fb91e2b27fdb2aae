#include "ltc/ltc_fit.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <thread>

#include "common/cloth_dfg_reference.hpp"
#include "common/ibl_reference.hpp"
#include "common/lights_reference.hpp"
#include "common/microfacet_reference.hpp"

namespace mb::ltc {
namespace {

using ref::Vec3;
using ref::ltc::Mat3;

constexpr double kPi = ref::kPi;

// The lobe a table stands for at view v (n = z): its value D V (n.l) and a sampling of it
// with its density, for the fit's error estimate (combined with D_M's own samples).
class TargetLobe {
 public:
  TargetLobe(double alpha, double NoV)
      : alpha(alpha), NoV(NoV), v{std::sqrt(std::max(0.0, 1.0 - NoV * NoV)), 0.0, NoV} {}
  virtual ~TargetLobe() = default;
  virtual double value(const Vec3& l) const = 0;  // D V (n.l), 0 below the horizon
  virtual double pdf(const Vec3& l) const = 0;
  virtual Vec3 sample(double u1, double u2) const = 0;

  // The lobe's mean direction (unnormalized), estimated on the points `pts` of [0, 1)^2: by
  // default from the lobe's own samples (the estimator value / pdf).
  virtual Vec3 meanDirection(const std::vector<std::array<double, 2>>& pts) const {
    Vec3 mean;
    for (const auto& u : pts) {
      const Vec3 l = sample(u[0], u[1]);
      const double q = pdf(l);
      if (q > 0.0) mean = mean + l * (value(l) / q);
    }
    return mean;
  }

  const double alpha, NoV;
  const Vec3 v;
};

// GGX with the height-correlated Smith V, sampled by its visible normals (Heitz 2018,
// "Sampling the GGX Distribution of Visible Normals"), whose density is G1(v) D(h) / (4 n.v)
// in l.
class GgxLobe final : public TargetLobe {
 public:
  GgxLobe(double alpha, double NoV) : TargetLobe(alpha, NoV), g1v_(1.0 / (1.0 + ref::smithGgxLambda(NoV, alpha))) {}

  double value(const Vec3& l) const override {
    if (!(l.z > 0.0)) return 0.0;
    const Vec3 s = v + l;
    const double NoH = s.z / ref::length(s);
    return ref::lights::ggxD(NoH, alpha) * ref::smithGgxCorrelatedV(NoV, l.z, alpha) * l.z;
  }

  double pdf(const Vec3& l) const override {
    const Vec3 s = v + l;
    const double len = ref::length(s);
    if (!(len > 1e-12)) return 0.0;
    const Vec3 h = s / len;
    if (!(h.z > 0.0) || !(ref::dot(v, h) > 0.0)) return 0.0;
    return g1v_ * ref::lights::ggxD(h.z, alpha) / (4.0 * NoV);
  }

  Vec3 sample(double u1, double u2) const override {
    const Vec3 vh = ref::normalize(Vec3{alpha * v.x, alpha * v.y, v.z});
    const double lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = lensq > 0.0 ? Vec3{-vh.y, vh.x, 0.0} / std::sqrt(lensq) : Vec3{1.0, 0.0, 0.0};
    const Vec3 t2 = ref::cross(vh, t1);
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    const double p1 = r * std::cos(phi);
    const double s = 0.5 * (1.0 + vh.z);
    const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
    const Vec3 h = ref::normalize(Vec3{alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)});
    return h * (2.0 * ref::dot(v, h)) - v;
  }

 private:
  double g1v_;
};

// The sheen lobe: Charlie D(h) = (2 + 1/alpha) sin^(1/alpha)(theta_h) / (2 pi) (Estevez &
// Kulla 2017, eq. 2) and V = 1 / (4 (n.l + n.v - n.l n.v)) (Neubelt & Pettineo 2013). Sampled
// by its normals: D(h) (n.h) is normalized, with the CDF sin^(2 + 1/alpha)(theta_h) in theta_h,
// so sin(theta_h) = u1^(1 / (2 + 1/alpha)); the density in l is D(h) (n.h) / (4 v.h). Half
// vectors facing away from v reflect to no light (density 0 there).
class CharlieLobe final : public TargetLobe {
 public:
  using TargetLobe::TargetLobe;

  double value(const Vec3& l) const override { return ref::ltc::charlieLobeLocal(v, alpha, l); }

  double pdf(const Vec3& l) const override {
    const Vec3 s = v + l;
    const double len = ref::length(s);
    if (!(len > 1e-12)) return 0.0;
    const Vec3 h = s / len;
    const double VoH = ref::dot(v, h);
    if (!(h.z > 0.0) || !(VoH > 0.0)) return 0.0;
    return ref::ltc::charlieD(std::max(0.0, 1.0 - h.z * h.z), alpha) * h.z / (4.0 * VoH);
  }

  Vec3 sample(double u1, double u2) const override {
    const double sinH = std::pow(u1, 1.0 / (2.0 + 1.0 / alpha));
    const double cosH = std::sqrt(std::max(0.0, 1.0 - sinH * sinH)), phi = 2.0 * kPi * u2;
    const Vec3 h{sinH * std::cos(phi), sinH * std::sin(phi), cosH};
    return h * (2.0 * ref::dot(v, h)) - v;
  }

  // Most normals of a smooth sheen reflect v below the horizon: at n.v = 1, l.z = 2 cos^2(theta_h)
  // - 1 > 0 needs sin(theta_h) < 1/sqrt(2), which the sampler draws with probability
  // 0.5^(1 + 1/(2 alpha)), 1.5e-8 at alpha = 0.02, so 32 x 32 samples find no light and their
  // mean is no direction. The normal
  // samples are combined here with cosine samples by the balance heuristic (Veach 1997), as the
  // fit's error is.
  Vec3 meanDirection(const std::vector<std::array<double, 2>>& pts) const override {
    Vec3 mean;
    auto add = [&](const Vec3& l) {
      const double q = pdf(l) + std::max(l.z, 0.0) / kPi;
      if (q > 0.0) mean = mean + l * (value(l) / q);
    };
    for (const auto& u : pts) {
      add(sample(u[0], u[1]));
      const double r = std::sqrt(u[0]), phi = 2.0 * kPi * u[1];
      add(Vec3{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u[0]))});
    }
    return mean;
  }
};

std::unique_ptr<TargetLobe> makeLobe(LobeKind kind, double alpha, double NoV) {
  if (kind == LobeKind::Charlie) return std::make_unique<CharlieLobe>(alpha, NoV);
  return std::make_unique<GgxLobe>(alpha, NoV);
}

// Stratified points of [0, 1)^2, one per cell of a k x k grid, at the cell centres: the
// error is a deterministic function of the matrix, so the minimizer sees a smooth surface.
std::vector<std::array<double, 2>> grid(uint32_t k) {
  std::vector<std::array<double, 2>> g;
  g.reserve(size_t{k} * k);
  for (uint32_t a = 0; a < k; ++a)
    for (uint32_t b = 0; b < k; ++b) g.push_back({(a + 0.5) / k, (b + 0.5) / k});
  return g;
}

Mat3 matrixOf(const LtcShape& s, const Vec3& mean) {
  const Vec3 x{mean.z, 0.0, -mean.x}, y{0.0, 1.0, 0.0}, z = mean;
  // M = [x y z] [[a, 0, b], [0, c, 0], [0, 0, 1]]
  const Vec3 c0 = x * s.a, c1 = y * s.c, c2 = x * s.b + z;
  return Mat3{{{c0.x, c1.x, c2.x}, {c0.y, c1.y, c2.y}, {c0.z, c1.z, c2.z}}};
}

// The cubic error Int |p - D_M|^3 dl of D_M against the normalized lobe p = value / norm,
// estimated with both sample sets combined by the balance heuristic (Veach 1997): the
// lobe's visible-normal samples and D_M's own (cosine samples mapped by M).
class Objective {
 public:
  Objective(const TargetLobe& lobe, double norm, const Vec3& mean, const std::vector<std::array<double, 2>>& pts)
      : lobe_(lobe), norm_(norm), mean_(mean), pts_(pts) {
    for (const auto& u : pts) {
      const Vec3 l = lobe.sample(u[0], u[1]);
      lobeSamples_.push_back({l, lobe.value(l) / norm, lobe.pdf(l)});
      const double r = std::sqrt(u[0]), phi = 2.0 * kPi * u[1];
      cosineSamples_.push_back({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u[0]))});
    }
  }

  double operator()(const LtcShape& s) const {
    if (!(s.a > 1e-7) || !(s.c > 1e-7) || !std::isfinite(s.b)) return std::numeric_limits<double>::infinity();
    const Mat3 m = matrixOf(s, mean_);
    const Mat3 minv = ref::ltc::inverse(m);
    double sum = 0.0;
    for (const auto& smp : lobeSamples_) {
      const double d = ref::ltc::density(minv, smp.l);
      const double q = smp.pdf + d;
      if (q > 0.0) sum += std::pow(std::abs(smp.p - d), 3.0) / q;
    }
    for (const Vec3& o : cosineSamples_) {
      const Vec3 l = ref::normalize(ref::ltc::mul(m, o));
      const double d = ref::ltc::density(minv, l);
      const double p = lobe_.value(l) / norm_;
      const double q = lobe_.pdf(l) + d;
      if (q > 0.0) sum += std::pow(std::abs(p - d), 3.0) / q;
    }
    return sum / static_cast<double>(pts_.size());
  }

 private:
  struct LobeSample {
    Vec3 l;
    double p, pdf;
  };
  const TargetLobe& lobe_;
  double norm_;
  Vec3 mean_;
  const std::vector<std::array<double, 2>>& pts_;
  std::vector<LobeSample> lobeSamples_;
  std::vector<Vec3> cosineSamples_;
};

// Nelder and Mead's simplex method (1965) with the standard coefficients (reflection 1,
// expansion 2, contraction 1/2, shrink 1/2), over (a, b, c).
struct Minimum {
  LtcShape shape;
  double value;
  uint32_t iterations;
};

Minimum nelderMead(const Objective& f, const LtcShape& start, uint32_t maxIterations) {
  using P = std::array<double, 3>;
  auto toShape = [](const P& p) { return LtcShape{p[0], p[1], p[2]}; };
  const P p0{start.a, start.b, start.c};
  std::array<P, 4> x{p0, p0, p0, p0};
  for (int k = 0; k < 3; ++k) x[k + 1][k] += std::max(0.05 * std::abs(p0[k]), 0.01);
  std::array<double, 4> fx;
  for (int k = 0; k < 4; ++k) fx[k] = f(toShape(x[k]));
  uint32_t it = 0;
  for (; it < maxIterations; ++it) {
    std::array<int, 4> order{0, 1, 2, 3};
    std::sort(order.begin(), order.end(), [&](int i, int j) { return fx[i] < fx[j]; });
    std::array<P, 4> xs;
    std::array<double, 4> fs;
    for (int k = 0; k < 4; ++k) {
      xs[k] = x[order[k]];
      fs[k] = fx[order[k]];
    }
    x = xs;
    fx = fs;
    if (std::abs(fx[3] - fx[0]) <= 1e-12 * (std::abs(fx[0]) + 1e-30)) break;
    P centroid{};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 3; ++d) centroid[d] += x[k][d] / 3.0;
    auto along = [&](double t) {
      P p;
      for (int d = 0; d < 3; ++d) p[d] = centroid[d] + t * (x[3][d] - centroid[d]);
      return p;
    };
    const P r = along(-1.0);
    const double fr = f(toShape(r));
    if (fr < fx[0]) {
      const P e = along(-2.0);
      const double fe = f(toShape(e));
      if (fe < fr) {
        x[3] = e;
        fx[3] = fe;
      } else {
        x[3] = r;
        fx[3] = fr;
      }
    } else if (fr < fx[2]) {
      x[3] = r;
      fx[3] = fr;
    } else {
      const bool outside = fr < fx[3];
      const P c = along(outside ? -0.5 : 0.5);
      const double fc = f(toShape(c));
      if (fc < (outside ? fr : fx[3])) {
        x[3] = c;
        fx[3] = fc;
      } else {
        for (int k = 1; k < 4; ++k) {
          for (int d = 0; d < 3; ++d) x[k][d] = x[0][d] + 0.5 * (x[k][d] - x[0][d]);
          fx[k] = f(toShape(x[k]));
        }
      }
    }
  }
  int best = static_cast<int>(std::min_element(fx.begin(), fx.end()) - fx.begin());
  return {toShape(x[best]), fx[best], it};
}

// What one entry's fit works on: the lobe, its magnitudes, its mean direction and the samples.
struct EntrySetup {
  std::unique_ptr<TargetLobe> lobe;
  double norm = 0, fresnel = 0;
  std::vector<std::array<double, 2>> pts;
  Vec3 mean;

  EntrySetup(double roughness, double NoV, const FitSettings& settings)
      : lobe(makeLobe(settings.lobe, std::max(roughness * roughness, minAlpha(settings.lobe)), NoV)),
        pts(grid(settings.samples)) {
    if (settings.lobe == LobeKind::Charlie) {
      norm = ref::clothDfgIntegral(NoV, lobe->alpha);
    } else {
      const ref::DfgIntegrals dfg = ref::dfgIntegrals(NoV, lobe->alpha);
      norm = dfg.gv;
      fresnel = dfg.gvFc;
    }
    mean = lobe->meanDirection(pts);
    mean.y = 0.0;  // the lobe is symmetric about the plane of n and v
    // A lobe too small for a double to hold (a smooth sheen seen head-on: norm 0) has no
    // direction; the normal stands in.
    mean = ref::length(mean) > 0.0 ? ref::normalize(mean) : Vec3{0.0, 0.0, 1.0};
  }
};

}  // namespace

const char* lobeName(LobeKind k) { return k == LobeKind::Charlie ? "charlie" : "ggx"; }

double minAlpha(LobeKind k) { return k == LobeKind::Charlie ? kMinCharlieAlpha : kMinAlpha; }

double tableRoughness(uint32_t i, uint32_t size) { return static_cast<double>(i) / (size - 1); }

double tableNoV(uint32_t j, uint32_t size) {
  const double u = static_cast<double>(j) / (size - 1);
  return std::max(1.0 - u * u, kMinNoV);
}

LtcEntry fitEntry(double roughness, double NoV, const LtcShape& start, const FitSettings& settings) {
  const EntrySetup setup(roughness, NoV, settings);
  LtcEntry e;
  e.roughness = roughness;
  e.NoV = NoV;
  e.norm = setup.norm;
  e.fresnel = setup.fresnel;
  const Objective objective(*setup.lobe, e.norm, setup.mean, setup.pts);
  // Nothing to fit to a lobe of magnitude 0 (it underflows): the start, the rougher neighbour,
  // keeps the column continuous.
  const Minimum best = e.norm > 0.0 ? nelderMead(objective, start, settings.maxIterations) : Minimum{start, 0.0, 0};
  e.shape = best.shape;
  e.error = best.value;
  e.iterations = best.iterations;
  e.m = matrixOf(best.shape, setup.mean);
  e.minv = ref::ltc::inverse(e.m);
  const double scale = e.minv[1][1];
  for (auto& row : e.minv)
    for (double& x : row) x /= scale;
  return e;
}

double fitError(double roughness, double NoV, const LtcShape& shape, const FitSettings& settings) {
  const EntrySetup setup(roughness, NoV, settings);
  return Objective(*setup.lobe, setup.norm, setup.mean, setup.pts)(shape);
}

LtcShape shapeOf(double roughness, double NoV, const ref::ltc::Mat3& minv, const FitSettings& settings) {
  const EntrySetup setup(roughness, NoV, settings);
  const ref::ltc::Mat3 m = ref::ltc::inverse(minv);
  // S = B^T M with B = [x y z] (matrixOf), scaled so that S[2][2] = 1.
  const Vec3 x{setup.mean.z, 0.0, -setup.mean.x}, y{0.0, 1.0, 0.0}, z = setup.mean;
  auto column = [&](int c) { return Vec3{m[0][c], m[1][c], m[2][c]}; };
  const double s22 = ref::dot(z, column(2));
  return {ref::dot(x, column(0)) / s22, ref::dot(x, column(2)) / s22, ref::dot(y, column(1)) / s22};
}

std::vector<LtcEntry> fitTable(uint32_t size, const FitSettings& settings, uint32_t threads) {
  std::vector<LtcEntry> table(size_t{size} * size);
  std::atomic<uint32_t> nextColumn{0};
  auto work = [&] {
    for (uint32_t j = nextColumn++; j < size; j = nextColumn++) {
      LtcShape start;  // the roughest lobe is close to a cosine: start from M = the rotation
      for (uint32_t i = size; i-- > 0;) {
        LtcEntry& e = table[size_t{i} * size + j];
        e = fitEntry(tableRoughness(i, size), tableNoV(j, size), start, settings);
        start = e.shape;
      }
    }
  };
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (uint32_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  return table;
}

}  // namespace mb::ltc
