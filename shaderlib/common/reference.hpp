// Double-precision reference framework. Every brick's C++ reference is written from the
// published equation in its most direct form (DESIGN.md "The reference is independent"),
// never by compiling the GLSL as C++. References register themselves by brick id; the
// registry records their C++ parameter types so a test can check them against the
// manifest's slot signatures.
#pragma once
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "core/value_type.hpp"

namespace mb::ref {

inline constexpr double kPi = std::numbers::pi;

struct Vec3 {
  double x = 0, y = 0, z = 0;
  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
};
inline Vec3 operator*(double s, const Vec3& v) { return v * s; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(const Vec3& a) { return a / length(a); }
inline double clamp01(double x) { return x < 0 ? 0 : (x > 1 ? 1 : x); }
inline Vec3 splat(double s) { return {s, s, s}; }
inline Vec3 mix(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

// Smallest n.v the shading geometry lets through; the same constant as common.glsl, so
// that reference and GPU agree on the definition of the geometry (Filament's clampNoV).
inline constexpr double kMinNoV = 1e-4;

// The shading geometry, built from vectors exactly as common.glsl's makeGeometry does:
// vectors are normalized, h is the half vector, dot products are clamped to [0, 1] and
// n.v to at least kMinNoV.
struct Geometry {
  Vec3 n, v, l, h;
  double NoV = 0, NoL = 0, NoH = 0, LoH = 0, VoH = 0;
};
Geometry makeGeometry(const Vec3& n, const Vec3& v, const Vec3& l);

// While alive, makeGeometry forms the half vector from v (1 + skew) + l (1 - skew) instead of
// v + l: the effect of fp32 normalize() returning v and l with lengths 1 +- a few ulps. Near
// v = -l that length error turns into a half-vector direction error of ~skew / |v + l|,
// which no fp32 shader avoids. The validator uses it to measure input conditioning
// (compiler/validate/probe_program.cpp); references never set it.
class ScopedHalfVectorSumSkew {
 public:
  explicit ScopedHalfVectorSumSkew(double skew);
  ~ScopedHalfVectorSumSkew();
  ScopedHalfVectorSumSkew(const ScopedHalfVectorSumSkew&) = delete;
  ScopedHalfVectorSumSkew& operator=(const ScopedHalfVectorSumSkew&) = delete;

 private:
  double previous_;
};

// A reference bound to a brick id: parameter types as they appear in the slot signature,
// and an evaluator over packed doubles (Geometry = 9 doubles n, v, l).
struct Reference {
  std::vector<ValueType> params;
  ValueType returns = ValueType::Float;
  std::function<void(const double* in, double* out)> eval;
};

class Registry {
 public:
  static Registry& references();    // the brick's equation, in double
  static Registry& groundTruths();  // the exact quantity an approximating brick stands in for
  bool add(const std::string& id, Reference r);
  const Reference* find(const std::string& id) const;
  const std::map<std::string, Reference>& all() const { return entries_; }

 private:
  std::map<std::string, Reference> entries_;
};

namespace detail {
template <class T>
struct TypeOf;
template <>
struct TypeOf<double> {
  static constexpr ValueType value = ValueType::Float;
  static double read(const double*& p) { return *p++; }
};
template <>
struct TypeOf<Vec3> {
  static constexpr ValueType value = ValueType::Vec3;
  static Vec3 read(const double*& p) {
    Vec3 v{p[0], p[1], p[2]};
    p += 3;
    return v;
  }
};
template <>
struct TypeOf<Geometry> {
  static constexpr ValueType value = ValueType::Geometry;
  static Geometry read(const double*& p) {
    Vec3 n{p[0], p[1], p[2]}, v{p[3], p[4], p[5]}, l{p[6], p[7], p[8]};
    p += 9;
    return makeGeometry(n, v, l);
  }
};
inline void write(double* out, double v) { out[0] = v; }
inline void write(double* out, const Vec3& v) {
  out[0] = v.x;
  out[1] = v.y;
  out[2] = v.z;
}
}  // namespace detail

template <class R, class... A>
Reference makeReference(R (*fn)(A...)) {
  Reference r;
  r.params = {detail::TypeOf<std::decay_t<A>>::value...};
  r.returns = detail::TypeOf<std::decay_t<R>>::value;
  r.eval = [fn](const double* in, double* out) {
    const double* p = in;
    // Braced init guarantees left-to-right evaluation of the reads.
    std::tuple<std::decay_t<A>...> args{detail::TypeOf<std::decay_t<A>>::read(p)...};
    detail::write(out, std::apply(fn, args));
  };
  return r;
}

}  // namespace mb::ref

#define MB_CONCAT_INNER(a, b) a##b
#define MB_CONCAT(a, b) MB_CONCAT_INNER(a, b)
// Registers the reference of brick ID (a string literal) to FN.
#define MB_REFERENCE(ID, FN)                                                 \
  [[maybe_unused]] static const bool MB_CONCAT(mb_reference_, __COUNTER__) = \
      ::mb::ref::Registry::references().add(ID, ::mb::ref::makeReference(FN))
// Registers the ground truth an approximating brick ID stands in for.
#define MB_GROUND_TRUTH(ID, FN)                                                 \
  [[maybe_unused]] static const bool MB_CONCAT(mb_ground_truth_, __COUNTER__) = \
      ::mb::ref::Registry::groundTruths().add(ID, ::mb::ref::makeReference(FN))
