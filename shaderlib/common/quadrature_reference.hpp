// Adaptive Gauss-Legendre quadrature in double, shared by the integrated ground truths (the
// split-sum DFG integrals of ibl_reference.hpp and the cloth albedo of
// cloth_dfg_reference.hpp). Each interval is integrated by the 8-point rule and by the same
// rule on its two halves; the difference is the error estimate (the halves' result is far
// more accurate than the whole's, so it overestimates the halves' error). An interval whose
// estimate is above its share of the tolerance is split.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>

namespace mb::ref {

namespace detail_quad {

// Gauss-Legendre nodes/weights on [-1, 1] by Newton on P_n, for an n known at run time
// (the DFG LUT kernel's rule, lut_kernel.hpp, chooses its node counts as data).
inline void gaussLegendreNodes(int n, double* x, double* w) {
  constexpr double kPiLocal = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double z = std::cos(kPiLocal * (i + 0.75) / (n + 0.5));
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = 0;
      for (int k = 1; k <= n; ++k) {
        double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      double dp = n * (z * p0 - p1) / (z * z - 1.0);
      double dz = p0 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) {
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        break;
      }
    }
  }
}

// The same nodes for a compile-time N (computed once).
template <int N>
struct GaussLegendre {
  std::array<double, N> x{}, w{};
  GaussLegendre() { gaussLegendreNodes(N, x.data(), w.data()); }
};

}  // namespace detail_quad

// K integrands evaluated together (f fills an std::array<double, K>), so that channels that
// share their geometry share the adaptive subdivision. The error measure of an interval is
// the largest over the K components.
// K integrands evaluated together (f fills an std::array<double, K>), so that channels that
// share their geometry share the adaptive subdivision. The error measure of an interval is
// the largest over the K components. integrate(f, a, b, tol): absolute tolerance tol for that
// interval; a half gets half of its parent's share, but never less than 1/100 of tol (an
// integrand that is itself an adaptive integral carries noise of its own tolerance, which
// the caller keeps below that floor), nor less than 1e-14 of the value (rounding).
template <size_t K>
class AdaptiveGaussLegendre {
 public:
  using Values = std::array<double, K>;

  template <class F>
  Values integrate(const F& f, double a, double b, double tol) {
    Values whole = rule(f, a, b);
    return refine(f, a, b, whole, tol, 0.01 * tol, kMaxDepth);
  }
  // Sum of the accepted intervals' error estimates (|halves - whole|): an upper estimate of
  // the error of what was returned, reported by the references' convergence tests.
  double errorEstimate() const { return errorEstimate_; }
  size_t evaluations() const { return evaluations_; }

 private:
  static constexpr int kMaxDepth = 40;
  static constexpr size_t kMaxEvaluations = 2000000;
  template <class F>
  Values rule(const F& f, double a, double b) {
    static const detail_quad::GaussLegendre<8> gl;
    Values s{};
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (int i = 0; i < 8; ++i) {
      Values v = f(mid + half * gl.x[i]);
      for (size_t k = 0; k < K; ++k) s[k] += gl.w[i] * v[k];
    }
    for (size_t k = 0; k < K; ++k) s[k] *= half;
    evaluations_ += 8;
    return s;
  }
  template <class F>
  Values refine(const F& f, double a, double b, const Values& whole, double tol, double floor, int depth) {
    const double m = 0.5 * (a + b);
    Values left = rule(f, a, m), right = rule(f, m, b), sum{};
    double err = 0.0, scale = 0.0;
    for (size_t k = 0; k < K; ++k) {
      sum[k] = left[k] + right[k];
      err = std::max(err, std::fabs(sum[k] - whole[k]));
      scale = std::max(scale, std::fabs(left[k]) + std::fabs(right[k]));
    }
    // The evaluation budget is a safety net against an unreachable tolerance (it is far above
    // what the references use: < 1e5 evaluations of the outer rule per call).
    if (err <= std::max(tol, floor) || err <= 1e-14 * scale || depth == 0 || !(m > a && m < b) ||
        evaluations_ > kMaxEvaluations) {
      errorEstimate_ += err;
      return sum;
    }
    Values l = refine(f, a, m, left, 0.5 * tol, floor, depth - 1);
    Values r = refine(f, m, b, right, 0.5 * tol, floor, depth - 1);
    for (size_t k = 0; k < K; ++k) sum[k] = l[k] + r[k];
    return sum;
  }
  double errorEstimate_ = 0.0;
  size_t evaluations_ = 0;
};

}  // namespace mb::ref
