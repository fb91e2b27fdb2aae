#include "stress/stress_inputs.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "validate/precision_domain.hpp"

namespace mb {
namespace {

struct V3 {
  double x = 0, y = 0, z = 0;
};
V3 scaled(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double norm(V3 a) { return std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z); }

// A direction at cosine c from n = +z: the stored z component is c itself, so n.v is exact.
V3 atCosine(double c, double azimuth) {
  double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  if (azimuth == 0.0) return {s, 0, c};   // same side as v
  if (azimuth == 1.0) return {-s, 0, c};  // mirror side: n.h = 1 when the cosines match
  return {0, s, c};                       // 90 degrees azimuth
}

struct GeometryCase {
  V3 n, v, l;
};

// Rounding-level slack when checking a value against a declared bound.
constexpr double kDomainSlack = 1e-6;
bool within(double x, const Range& r) { return x >= r.lo - kDomainSlack && x <= r.hi + kDomainSlack; }

std::vector<double> uniqueSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::vector<GeometryCase> geometryCases(const GeometryDomain& d) {
  const V3 n{0, 0, 1};
  std::vector<double> cosines = uniqueSorted({0.0, 1e-7, 1e-4, 1e-2, 0.1, 0.5, 1.0, std::clamp(d.NoV.lo, -1.0, 1.0),
                                              std::clamp(d.NoL.lo, -1.0, 1.0), std::clamp(d.NoV.hi, -1.0, 1.0)});
  std::vector<GeometryCase> cases;
  for (double cv : cosines)
    for (double cl : cosines)
      for (double azimuth : {0.0, 1.0, 2.0}) cases.push_back({n, atCosine(cv, 0.0), atCosine(cl, azimuth)});
  // v = -l exactly (no half vector) and nearly (l.h -> 0): back-facing l unless n.v = 0.
  for (double cv : cosines) {
    V3 v = atCosine(cv, 0.0);
    for (double eps : {0.0, 1e-6, 1e-3}) cases.push_back({n, v, {-v.x, eps, -v.z}});
  }
  // Back-facing light and back-facing view.
  for (double cv : {1e-2, 0.5})
    for (double c : {1e-4, 0.1, 0.5, 1.0}) cases.push_back({n, atCosine(cv, 0.0), atCosine(-c, 1.0)});
  for (double c : {1e-4, 0.1, 1.0}) cases.push_back({n, atCosine(-c, 0.0), atCosine(0.5, 2.0)});
  // Zero-length vectors (always out of domain).
  const V3 zero{}, v{0.6, 0, 0.8}, l{-0.6, 0, 0.8};
  cases.push_back({zero, v, l});
  cases.push_back({n, zero, l});
  cases.push_back({n, v, zero});
  return cases;
}

// One value of one input, and whether it lies in the domain.
struct Candidate {
  std::vector<double> components;
  bool inDomain = true;
};

std::vector<Candidate> floatCandidates(RoughnessKind kind, const Range& r) {
  std::vector<double> values{r.lo, r.hi, 0.5 * (r.lo + r.hi), 0.0, 1e-4, 1.0};
  if (kind != RoughnessKind::None) {
    values.push_back(roughnessFloor(kind, ShaderPrecision::Fp32));
    values.push_back(roughnessFloor(kind, ShaderPrecision::Fp16));
  }
  std::vector<Candidate> out;
  // Declared ends and middle first: index 2 (the middle) is the baseline of one-at-a-time.
  for (double v : values) {
    bool seen = std::any_of(out.begin(), out.end(), [&](const Candidate& c) { return c.components[0] == v; });
    if (!seen) out.push_back({{v}, within(v, r)});
  }
  return out;
}

std::vector<Candidate> vectorCandidates(int components, const Range& r) {
  std::vector<std::vector<double>> values;
  double mid = 0.5 * (r.lo + r.hi);
  if (r.lo >= 0.0) {
    for (double s : {r.lo, r.hi, mid, 0.0, 1.0}) values.push_back(std::vector<double>(components, s));
  } else {
    // Signed: a direction-like vector. Axis and diagonal vectors, a short one, and zero.
    values.push_back(std::vector<double>(components, r.lo));
    values.push_back(std::vector<double>(components, r.hi));
    for (int axis = 0; axis < components; ++axis) {
      std::vector<double> e(components, 0.0);
      e[axis] = 1.0;
      values.push_back(e);
    }
    std::vector<double> shortVec(components, 0.0);
    shortVec[0] = 1e-3;
    values.push_back(shortVec);
    values.push_back(std::vector<double>(components, 0.0));
  }
  std::vector<Candidate> out;
  for (const auto& v : values) {
    if (std::any_of(out.begin(), out.end(), [&](const Candidate& c) { return c.components == v; })) continue;
    bool in = std::all_of(v.begin(), v.end(), [&](double x) { return within(x, r); });
    bool zero = std::all_of(v.begin(), v.end(), [](double x) { return x == 0.0; });
    out.push_back({v, in && !(zero && r.lo < 0.0)});
  }
  return out;
}

// Index tuples into each input's candidates: the full product when it is small, else each
// input varied alone around the baseline (index 2, else 0), plus all-low and all-high.
std::vector<std::vector<size_t>> combinations(const std::vector<std::vector<Candidate>>& inputs) {
  constexpr size_t kMaxProduct = 64;
  size_t product = 1;
  for (const auto& c : inputs) product = std::min(product * c.size(), kMaxProduct + 1);
  std::vector<std::vector<size_t>> out;
  if (product <= kMaxProduct) {
    std::vector<size_t> idx(inputs.size(), 0);
    for (size_t k = 0; k < product; ++k) {
      out.push_back(idx);
      for (size_t i = 0; i < idx.size(); ++i) {
        if (++idx[i] < inputs[i].size()) break;
        idx[i] = 0;
      }
    }
    return out;
  }
  std::vector<size_t> base;
  for (const auto& c : inputs) base.push_back(c.size() > 2 ? 2 : 0);
  out.push_back(std::vector<size_t>(inputs.size(), 0));
  out.push_back(std::vector<size_t>(inputs.size(), 1));
  for (size_t i = 0; i < inputs.size(); ++i) {
    for (size_t k = 0; k < inputs[i].size(); ++k) {
      std::vector<size_t> idx = base;
      idx[i] = k;
      out.push_back(idx);
    }
  }
  return out;
}

bool isGeometryInput(const ProbeInput& in, bool hasGeometry) {
  return hasGeometry && (in.name == "n" || in.name == "v" || in.name == "l");
}

}  // namespace

StressInputs generateStressInputs(const ProbeLayout& layout, const SampleDomain& domain, ShaderPrecision precision,
                                  uint64_t randomSamples, uint64_t seed) {
  const bool hasGeometry = layout.find("n") && layout.find("v") && layout.find("l");
  std::vector<const ProbeInput*> params;
  std::vector<std::vector<Candidate>> candidates;
  for (const auto& in : layout.inputs) {
    if (isGeometryInput(in, hasGeometry)) continue;
    auto it = domain.ranges.find(in.name);
    Range r = it != domain.ranges.end() ? it->second : Range{0.0, 1.0};
    params.push_back(&in);
    int n = componentCount(in.type);
    auto kind = domain.roughness.find(in.name);
    candidates.push_back(n == 1
                             ? floatCandidates(kind != domain.roughness.end() ? kind->second : RoughnessKind::None, r)
                             : vectorCandidates(n, r));
  }
  const auto combos = combinations(candidates);

  StressInputs out;
  std::vector<float> rec(layout.inStride, 0.0f);
  auto emitCombos = [&](bool geometryInDomain) {
    for (const auto& idx : combos) {
      bool in = geometryInDomain;
      for (size_t p = 0; p < params.size(); ++p) {
        const Candidate& c = candidates[p][idx[p]];
        in = in && c.inDomain;
        for (size_t k = 0; k < c.components.size(); ++k)
          rec[params[p]->offset + k] = static_cast<float>(c.components[k]);
      }
      out.records.insert(out.records.end(), rec.begin(), rec.end());
      out.inDomain.push_back(in ? 1 : 0);
    }
  };

  if (!hasGeometry) {
    emitCombos(true);
  } else {
    // Scale triples for (n, v, l): unit, each alone at 1e-3 and 1e3, all at 1e-3 and 1e3.
    std::vector<std::array<double, 3>> scales{{1, 1, 1}, {1e-3, 1e-3, 1e-3}, {1e3, 1e3, 1e3}};
    for (int which = 0; which < 3; ++which)
      for (double s : {1e-3, 1e3}) {
        std::array<double, 3> t{1, 1, 1};
        t[which] = s;
        scales.push_back(t);
      }
    for (const GeometryCase& g : geometryCases(domain.geometry)) {
      for (const auto& s : scales) {
        V3 vecs[3] = {scaled(g.n, s[0]), scaled(g.v, s[1]), scaled(g.l, s[2])};
        const char* names[3] = {"n", "v", "l"};
        for (int k = 0; k < 3; ++k) {
          const ProbeInput* pi = layout.find(names[k]);
          rec[pi->offset] = static_cast<float>(vecs[k].x);
          rec[pi->offset + 1] = static_cast<float>(vecs[k].y);
          rec[pi->offset + 2] = static_cast<float>(vecs[k].z);
        }
        bool in = norm(g.n) > 0 && norm(g.v) > 0 && norm(g.l) > 0;
        if (in) {
          double NoV = g.v.z / norm(g.v), NoL = g.l.z / norm(g.l);  // n = +z
          in = within(NoV, domain.geometry.NoV) && within(NoL, domain.geometry.NoL);
        }
        if (precision == ShaderPrecision::Fp16) in = in && s[0] == 1 && s[1] == 1 && s[2] == 1;
        emitCombos(in);
      }
    }
  }

  // Typical inputs too: the validation sampler's records, all in domain.
  if (randomSamples > 0) {
    std::vector<float> random = generateSamples(layout, domain, randomSamples, seed);
    out.records.insert(out.records.end(), random.begin(), random.end());
    out.inDomain.insert(out.inDomain.end(), randomSamples, 1);
  }
  return out;
}

}  // namespace mb
