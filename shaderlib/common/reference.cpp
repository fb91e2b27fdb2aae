#include "common/reference.hpp"

#include <cstring>
#include <stdexcept>
#include <tuple>

namespace mb::ref {

thread_local double tHalfVectorSumSkew = 0.0;

ScopedHalfVectorSumSkew::ScopedHalfVectorSumSkew(double skew) : previous_(tHalfVectorSumSkew) {
  tHalfVectorSumSkew = skew;
}
ScopedHalfVectorSumSkew::~ScopedHalfVectorSumSkew() { tHalfVectorSumSkew = previous_; }

// makeGeometry of the last call on this thread, by the exact bits of its arguments and skew:
// a composition passes the same n, v, l to most brick calls of a light (D, V, F, diffuse), and
// the result is a function of those bits alone, so reusing it changes no double.
struct GeometryMemo {
  double key[10] = {};
  Geometry g;
  bool valid = false;
};
thread_local GeometryMemo tLastGeometry;

static Geometry computeGeometry(const Vec3& n, const Vec3& v, const Vec3& l);

Geometry makeGeometry(const Vec3& n, const Vec3& v, const Vec3& l) {
  const double key[10] = {n.x, n.y, n.z, v.x, v.y, v.z, l.x, l.y, l.z, tHalfVectorSumSkew};
  GeometryMemo& memo = tLastGeometry;
  if (memo.valid && std::memcmp(key, memo.key, sizeof key) == 0) return memo.g;
  memo.g = computeGeometry(n, v, l);
  std::memcpy(memo.key, key, sizeof key);
  memo.valid = true;
  return memo.g;
}

static Geometry computeGeometry(const Vec3& n, const Vec3& v, const Vec3& l) {
  Geometry g;
  g.n = normalize(n);
  g.v = normalize(v);
  g.l = normalize(l);
  // The skew is zero except while the validator measures input conditioning.
  Vec3 sum = g.v * (1.0 + tHalfVectorSumSkew) + g.l * (1.0 - tHalfVectorSumSkew);
  double len2 = dot(sum, sum);
  // v = -l has no half vector; common.glsl picks n in that case, and so do we.
  g.h = len2 > 1e-24 ? sum / std::sqrt(len2) : g.n;
  g.NoV = std::max(dot(g.n, g.v), kMinNoV);
  g.NoL = clamp01(dot(g.n, g.l));
  g.NoH = clamp01(dot(g.n, g.h));
  g.LoH = clamp01(dot(g.l, g.h));
  g.VoH = clamp01(dot(g.v, g.h));
  return g;
}

Registry& Registry::references() {
  static Registry r;
  return r;
}

Registry& Registry::groundTruths() {
  static Registry r;
  return r;
}

bool Registry::add(const std::string& id, Reference r) {
  if (!entries_.emplace(id, std::move(r)).second)
    throw std::logic_error("duplicate reference registration for brick '" + id + "'");
  return true;
}

const Reference* Registry::find(const std::string& id) const {
  auto it = entries_.find(id);
  return it == entries_.end() ? nullptr : &it->second;
}

}  // namespace mb::ref
