#include "validate/sampler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace mb {

uint64_t SplitMix64::next() {
  uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double SplitMix64::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

namespace {

struct V3 {
  double x, y, z;
};
V3 add(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 scale(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot3(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross3(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
V3 unit(V3 a) { return scale(a, 1.0 / std::sqrt(dot3(a, a))); }

// Orthonormal frame (t, b, n) around a random normal.
struct Frame {
  V3 t, b, n;
  V3 toWorld(V3 local) const { return add(add(scale(t, local.x), scale(b, local.y)), scale(n, local.z)); }
};

Frame randomFrame(SplitMix64& rng) {
  double z = 2.0 * rng.uniform() - 1.0, phi = 2.0 * std::numbers::pi * rng.uniform();
  double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  V3 n{r * std::cos(phi), r * std::sin(phi), z};
  V3 helper = std::abs(n.z) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0};
  V3 t = unit(cross3(helper, n));
  return {t, cross3(n, t), n};
}

V3 fromAngles(double cosTheta, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return {s * std::cos(phi), s * std::sin(phi), cosTheta};
}

double lerp(const Range& r, double t) { return r.lo + (r.hi - r.lo) * t; }

// One random permutation of [0, count) per stratified dimension.
std::vector<uint32_t> permutation(uint64_t count, SplitMix64& rng) {
  std::vector<uint32_t> p(count);
  for (uint32_t i = 0; i < count; ++i) p[i] = i;
  for (uint64_t i = count; i > 1; --i) std::swap(p[i - 1], p[rng.next() % i]);
  return p;
}

struct GeometrySample {
  V3 n, v, l;  // local frame: n = +z
};

// Near-peak: h tilted from n by a log-spaced angle, l the mirror of v about h.
bool peakSample(const GeometryDomain& d, SplitMix64& rng, GeometrySample& out) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    double thetaH = std::exp(std::log(1e-5) + (std::log(0.5) - std::log(1e-5)) * rng.uniform());
    V3 h = fromAngles(std::cos(thetaH), 2.0 * std::numbers::pi * rng.uniform());
    // v at a random angle from h, l = reflect(-v, h).
    double cosD = lerp({0.05, 1.0}, rng.uniform());
    V3 hv = fromAngles(cosD, 2.0 * std::numbers::pi * rng.uniform());
    // Express hv in h's frame.
    V3 helper = std::abs(h.z) < 0.9 ? V3{0, 0, 1} : V3{1, 0, 0};
    V3 ht = unit(cross3(helper, h)), hb = cross3(h, ht);
    V3 v = add(add(scale(ht, hv.x), scale(hb, hv.y)), scale(h, hv.z));
    V3 l = add(scale(h, 2.0 * dot3(v, h)), scale(v, -1.0));
    if (v.z >= d.NoV.lo && v.z <= d.NoV.hi && l.z >= d.NoL.lo && l.z <= d.NoL.hi) {
      out = {{0, 0, 1}, v, l};
      return true;
    }
  }
  return false;
}

GeometrySample stratifiedSample(const GeometryDomain& d, double uNoV, double uNoL, SplitMix64& rng) {
  double phiV = 2.0 * std::numbers::pi * rng.uniform();
  double phiL = 2.0 * std::numbers::pi * rng.uniform();
  return {{0, 0, 1}, fromAngles(lerp(d.NoV, uNoV), phiV), fromAngles(lerp(d.NoL, uNoL), phiL)};
}

// Fixed cases every run includes, in this order.
std::vector<GeometrySample> edgeCases(const GeometryDomain& d) {
  std::vector<GeometrySample> e;
  V3 n{0, 0, 1};
  if (d.NoV.hi >= 1.0 && d.NoL.hi >= 1.0) e.push_back({n, n, n});  // n.h = 1 exactly
  double nov = std::max(d.NoV.lo, 1e-7), nol = std::max(d.NoL.lo, 0.0);
  e.push_back({n, fromAngles(nov, 0.0), fromAngles(std::min(d.NoL.hi, 1.0), 0.0)});  // grazing view
  e.push_back({n, fromAngles(std::min(d.NoV.hi, 1.0), 0.0), fromAngles(nol, 1.0)});  // grazing light
  e.push_back(
      {n, fromAngles(nov, 0.0), fromAngles(nov < d.NoL.lo ? d.NoL.lo : nov, std::numbers::pi)});  // mirror at grazing
  return e;
}

}  // namespace

std::vector<float> generateSamples(const ProbeLayout& layout, const SampleDomain& domain, uint64_t count,
                                   uint64_t seed) {
  SplitMix64 rng(seed * 0x2545F4914F6CDD1Dull + 1);
  std::vector<float> out(count * layout.inStride, 0.0f);
  bool hasGeometry = layout.find("n") && layout.find("v") && layout.find("l");
  auto edges = hasGeometry ? edgeCases(domain.geometry) : std::vector<GeometrySample>{};

  // Strata: one permutation per scalar component and two for (n.v, n.l).
  std::vector<std::vector<uint32_t>> strata;
  size_t scalarComponents = 0;
  for (const auto& in : layout.inputs)
    if (!(hasGeometry && (in.name == "n" || in.name == "v" || in.name == "l")))
      scalarComponents += static_cast<size_t>(componentCount(in.type));
  for (size_t k = 0; k < scalarComponents + 2; ++k) strata.push_back(permutation(count, rng));

  for (uint64_t i = 0; i < count; ++i) {
    float* rec = out.data() + i * layout.inStride;
    auto stratum = [&](size_t dim) { return (strata[dim][i] + rng.uniform()) / double(count); };

    if (hasGeometry) {
      GeometrySample g;
      if (i < edges.size()) {
        g = edges[i];
      } else if (i % 5 == 1 && peakSample(domain.geometry, rng, g)) {
        // near the specular peak
      } else {
        // Drawn one statement at a time: as two arguments of one call their order was unspecified,
        // so GCC and clang drew different samples (found by the clang sanitizer build). This is
        // the order GCC used, which the committed docs were generated with.
        double uNoL = stratum(scalarComponents + 1);
        double uNoV = stratum(scalarComponents);
        g = stratifiedSample(domain.geometry, uNoV, uNoL, rng);
      }
      Frame f = randomFrame(rng);
      // Interpolated vectors are not unit length: scale each by a factor in [0.8, 1.25].
      auto put = [&](const char* name, V3 local) {
        V3 w = scale(f.toWorld(local), 0.8 + 0.45 * rng.uniform());
        const ProbeInput* in = layout.find(name);
        rec[in->offset] = static_cast<float>(w.x);
        rec[in->offset + 1] = static_cast<float>(w.y);
        rec[in->offset + 2] = static_cast<float>(w.z);
      };
      put("n", g.n);
      put("v", g.v);
      put("l", g.l);
    }

    size_t dim = 0;
    for (const auto& in : layout.inputs) {
      if (hasGeometry && (in.name == "n" || in.name == "v" || in.name == "l")) continue;
      auto it = domain.ranges.find(in.name);
      Range r = it != domain.ranges.end() ? it->second : Range{0.0, 1.0};
      for (int k = 0; k < componentCount(in.type); ++k, ++dim) {
        double t = stratum(dim);
        // The first samples also pin each scalar to its range ends.
        if (i < 2 * edges.size() + 2) t = (i % 2 == 0) ? 0.0 : 1.0;
        rec[in.offset + k] = static_cast<float>(lerp(r, t));
      }
    }
  }
  return out;
}

}  // namespace mb
