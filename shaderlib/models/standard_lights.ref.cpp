// Reference of the standard model's point, spot, sphere and tube lights (seed 002 "Lighting
// model" / "Area lights", Karis 2013, Real Shading in Unreal Engine 4), in double and written
// from the equations, independently of standard_lights.glsl. Conventions: docs/models/lights.md.
#include <algorithm>
#include <cmath>
#include <functional>

#include "common/lights_reference.hpp"
#include "models/standard_reference.hpp"

namespace mb::ref::standard {
namespace {

// The light bricks' declared domain (sin alpha <= 0.95); nearer than radius / 0.95 the light
// is shaded as at that bound (docs/models/lights.md, "Degenerate lights").
constexpr double kMaxSinAlpha = 0.95;

Vec3 punctual(const ModelEvalInput& in, const Pixel& px, const Vec3& l, const Vec3& illuminance) {
  double NoL = clamp01(dot(in.frame.n, l));
  return light(in, px, l, l, 1.0, NoL, NoL) * illuminance;
}

// Filament's smooth spot cone: the cosine to the axis mapped linearly from cosOuter (0) to
// cosInner (1), clamped and squared; the width is kept >= 1e-4 as in the contract
// (docs/models.md).
double spotCone(const SpotLight& s, const Vec3& l) {
  double width = std::max(s.cosInner - s.cosOuter, 1e-4);
  double t = clamp01((dot(l * -1.0, s.axis) - s.cosOuter) / width);
  return t * t;
}

// A sphere of radius R centred at `toCenter`, as the surface sees it (Karis 2013, "Sphere
// Lights"): unit centre direction, sin of the angular radius, the horizon-wrapped cosine and
// the illuminance I * falloff at the centre distance (at the radius when inside the light).
struct SphereView {
  Vec3 l;
  double sinAlpha = 0, cosine = 0;
  Vec3 illuminance;
};

SphereView sphereView(const ModelEvalInput& in, const Vec3& toCenter, double radius, const Vec3& intensity,
                      double falloffRadius) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  SphereView s;
  double d = length(toCenter);
  s.l = d > 0.0 ? toCenter / d : n;
  double dLight = std::max(d, radius);
  s.sinAlpha = dLight > 0.0 ? std::min(radius / dLight, kMaxSinAlpha) : 0.0;
  s.cosine = in.scalar("sphere_horizon_wrap", Args().geometry(n, v, s.l) << s.sinAlpha);
  s.illuminance = intensity * in.scalar("light_falloff", Args() << s.l * dLight << falloffRadius);
  return s;
}

// chi+(n.h) of GGX D (Walter et al. 2007, eq. 33) for the representative direction lD: its
// half vector may face away from n when lD is far below the horizon; D is then 0. n.h <= 1e-4
// counts as facing away (the tube's -r direction has n.h = 0 exactly; see the GLSL).
constexpr double kMinNoH = 1e-4;
bool facing(double NoH) { return NoH > kMinNoH; }

// Karis 2013 "Tube Lights" line irradiance, E / I = (n.L0/|L0| + n.L1/|L1|) / (|L0||L1| + L0.L1),
// as a point light: direction w bisecting L0 and L1, distance^2 = |L0||L1| cos(theta / 2)
// (theta the angle the segment subtends; derivation in the GLSL and docs/models/lights.md).
Vec3 tubeEquivalentPoint(const Vec3& n, const Vec3& L0, const Vec3& L1) {
  double d0 = length(L0), d1 = length(L1);
  if (d0 == 0.0 || d1 == 0.0) return (d0 == 0.0 ? L0 : L1);  // an end at the shading point
  double theta = std::atan2(length(cross(L0, L1)), dot(L0, L1));
  Vec3 bisector = L0 / d0 + L1 / d1;
  double b = length(bisector);
  Vec3 w = b > 0.0 ? bisector / b : n;
  return w * std::sqrt(d0 * d1 * std::cos(0.5 * theta));
}

}  // namespace

Vec3 shadePoint(const ModelEvalInput& in, const Pixel& px, const PointLight& light) {
  Vec3 l = normalize(light.toLight);
  double falloff = in.scalar("light_falloff", Args() << light.toLight << light.falloffRadius);
  return punctual(in, px, l, light.intensity * falloff);
}

Vec3 shadeSpot(const ModelEvalInput& in, const Pixel& px, const SpotLight& light) {
  Vec3 l = normalize(light.toLight);
  double falloff = in.scalar("light_falloff", Args() << light.toLight << light.falloffRadius);
  return punctual(in, px, l, light.intensity * (falloff * spotCone(light, l)));
}

namespace {

// `light` (the BRDF of one direction) is hidden by a parameter of that name: the area lights
// call theirs `sphere` and `tube`.
Vec3 shadeSphereRepresentative(const ModelEvalInput& in, const Pixel& px, const SphereLight& sphere) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  SphereView s = sphereView(in, sphere.toCenter, sphere.radius, sphere.intensity, sphere.falloffRadius);
  // Karis's representative point, from the sphere_light_point role (a tube_light_point brick
  // with a zero-length segment); the centre direction where it has none.
  Vec3 lD =
      in.vec3("sphere_light_point", Args().geometry(n, v, s.l) << sphere.toCenter << sphere.toCenter << sphere.radius);
  if (!(dot(lD, lD) > 0.5)) lD = s.l;
  double energy = facing(makeGeometry(n, v, lD).NoH)
                      ? in.scalar("sphere_energy_normalization", Args().geometry(n, v, s.l) << px.alpha << s.sinAlpha)
                      : 0.0;
  return light(in, px, s.l, lD, energy, s.cosine, s.cosine) * s.illuminance;
}

Vec3 shadeTubeRepresentative(const ModelEvalInput& in, const Pixel& px, const TubeLight& tube) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  const Vec3 L0 = tube.toStart, L1 = tube.toEnd;
  Vec3 P = tubeEquivalentPoint(n, L0, L1);
  SphereView s = sphereView(in, P, tube.radius, tube.intensity, tube.falloffRadius);
  Vec3 lD = in.vec3("tube_light_point", Args().geometry(n, v, s.l) << L0 << L1 << tube.radius);
  // The brick's direction is undefined (NaN) when its point is the shading point itself (a
  // segment through it): the equivalent direction stands in.
  if (!(dot(lD, lD) > 0.5)) lD = s.l;
  double energy =
      facing(makeGeometry(n, v, lD).NoH)
          ? in.scalar("tube_energy_normalization", Args().geometry(n, v, lD) << px.alpha << L0 << L1 << tube.radius)
          : 0.0;
  return light(in, px, s.l, lD, energy, s.cosine, s.cosine) * s.illuminance;
}

// mb_ltc_view: v lifted about n to n.v = kLtcMinNoV where it is nearer the horizon or below it.
Vec3 ltcView(const Vec3& n, const Vec3& v) {
  const double NoV = dot(n, v);
  if (NoV >= kLtcMinNoV) return v;
  const Vec3 t = v - n * NoV;
  const double len = length(t);
  const Vec3 along =
      len > 1e-6 ? t / len : normalize(cross(n, std::abs(n.z) < 0.9 ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0}));
  return along * std::sqrt(1.0 - kLtcMinNoV * kLtcMinNoV) + n * kLtcMinNoV;
}

// Rectangle and disk lights by linearly transformed cosines (Heitz et al. 2016): a one-sided
// Lambertian emitter of luminance L sends L Int f (n.l)+ dw. `formFactor(n)` is the light's
// Int (n.l)+ dw / pi about n (the polygon brick with M = I); `lobe(n, v, texel, alpha)` the
// specular lobe's integral Int D V (n.l) dw about the frame (n, v), by the control-variate brick
// with the table's entry. Schlick's Fresnel splits over the table's magnitudes, f0 + (1 - f0)
// fresnel / norm (f90 = 1), times the multiscatter compensation; the diffuse brick at the
// centre's direction times the irradiance pi x form factor; the sheen its own lobe's integral
// `sheenLobe(n, v, texel, alpha)` by the sheen table, times sheenColor; the coat its own lobe
// about its normal. The tables' lobes are at alpha = r^2, r from kLtcMinRoughness, and the
// lobes' view is lifted to n.v >= kLtcMinNoV (standard_lights.glsl, MB_LTC_MIN_ROUGHNESS and
// mb_ltc_view).
template <typename FormFactor, typename Lobe, typename SheenLobe>
Vec3 ltcLight(const ModelEvalInput& in, const Pixel& px, const Vec3& toCenter, const Vec3& luminance,
              FormFactor formFactor, Lobe lobe, SheenLobe sheenLobe) {
  const Vec3 n = in.frame.n, v = in.frame.v;
  double d = length(toCenter);
  const Vec3 l = d > 0.0 ? toCenter / d : n;
  const Vec3 vb = ltcView(n, v);
  const double r = ltcRoughness(px.perceptualRoughness);
  const LtcTexel t = in.ltcAt(makeGeometry(n, vb, l).NoV, r);
  const double specular = lobe(n, vb, t, r * r);
  const double irradiance = kPi * formFactor(n);
  Vec3 Fr = (px.f0 * (t.norm - t.fresnel) + splat(t.fresnel)) * (specular / t.norm) * px.energyCompensation;
  double fd = in.scalar("diffuse", Args().geometry(n, v, l) << px.perceptualRoughness << px.alpha);
  Vec3 color = px.diffuseColor * (fd * irradiance) + Fr;
  if (in.has("sheen")) {
    const double rs = ltcRoughness(px.sheen.perceptualRoughness);
    const LtcTexel ts = in.sheenLtcAt(makeGeometry(n, vb, l).NoV, rs);
    color = color * px.sheen.scaling + px.sheen.color * sheenLobe(n, vb, ts, rs * rs);
  }
  if (in.has("clearcoat")) {
    const Vec3 nc = normalize(px.clearCoat.normal);
    const Vec3 vc = ltcView(nc, v);
    const double rc = ltcRoughness(px.clearCoat.perceptualRoughness);
    const LtcTexel tc = in.ltcAt(makeGeometry(nc, vc, l).NoV, rc);
    double attenuation = 1;
    Vec3 coat = clearCoatLtc(in, px.clearCoat, lobe(nc, vc, tc, rc * rc), tc, attenuation);
    color = color * attenuation + coat;
  }
  return color * luminance;
}

}  // namespace

// The form factor by the polygon bricks' roles (rect_light_ltc, disk_light_ltc) with M = I, the
// lobes by the control-variate roles (rect_light_ltc_cv, disk_light_ltc_cv) and the sheen's
// (rect_light_ltc_sheen, disk_light_ltc_sheen).
template <typename Light>
Vec3 shadePlanar(const ModelEvalInput& in, const Pixel& px, const Light& light, RoleName polygonRole, RoleName lobeRole,
                 RoleName sheenRole) {
  const Vec3 v = in.frame.v;
  auto lobeBy = [&](RoleName role) {
    return [&, role](const Vec3& n, const Vec3& view, const LtcTexel& t, double alpha) {
      return in.scalar(role, Args().geometry(n, view, n) << alpha << t.norm << t.m00 << t.m02 << t.m20 << t.m22
                                                         << light.toCenter << light.halfX << light.halfY);
    };
  };
  return ltcLight(
      in, px, light.toCenter, light.luminance,
      [&](const Vec3& n) {
        return in.scalar(polygonRole, Args().geometry(n, v, n)
                                          << 1.0 << 0.0 << 0.0 << 1.0 << light.toCenter << light.halfX << light.halfY);
      },
      lobeBy(lobeRole), lobeBy(sheenRole));
}

namespace {

// Sphere and tube lights by the "ltc" method (standard_lights.glsl, mb_shade_sphere and
// mb_shade_tube): the luminance I falloff(d) d^2 / A of a light of area A (pi R^2, and
// pi R^2 + 2 R len for a capsule seen broadside), the representative point below an equivalent
// angular radius sqrt(A / pi) / d of kLtcBlendStart, LTC above twice that, linear between; a
// tube also hands over to the representative point within two radii of its segment.
constexpr double kLtcBlendStart = 0.05;
double ltcBlend(double equivalentSinAlpha) { return std::clamp(equivalentSinAlpha / kLtcBlendStart - 1.0, 0.0, 1.0); }

Vec3 blend(const Vec3& representative, double w, const std::function<Vec3()>& ltc) {
  Vec3 color = w < 1.0 ? representative * (1.0 - w) : Vec3{0.0, 0.0, 0.0};
  return w > 0.0 ? color + ltc() * w : color;
}

}  // namespace

Vec3 shadeSphere(const ModelEvalInput& in, const Pixel& px, const SphereLight& sphere) {
  if (!in.bound("sphere_light_ltc_cv")) return shadeSphereRepresentative(in, px, sphere);
  const Vec3 n = in.frame.n, v = in.frame.v;
  const double R = sphere.radius, d = length(sphere.toCenter);
  const double dLight = std::max(d, R / kMaxSinAlpha);
  const double w = dLight > 0.0 ? ltcBlend(R / dLight) : 0.0;
  const Vec3 rp = w < 1.0 ? shadeSphereRepresentative(in, px, sphere) : Vec3{0.0, 0.0, 0.0};
  return blend(rp, w, [&] {
    const Vec3 l = d > 0.0 ? sphere.toCenter / d : n;
    const double falloff = in.scalar("light_falloff", Args() << l * dLight << sphere.falloffRadius);
    const Vec3 luminance = sphere.intensity * (falloff * dLight * dLight / (kPi * R * R));
    return ltcLight(
        in, px, sphere.toCenter, luminance,
        [&](const Vec3& nn) {
          return in.scalar("sphere_light_ltc", Args().geometry(nn, v, nn)
                                                   << 1.0 << 0.0 << 0.0 << 1.0 << sphere.toCenter << R);
        },
        [&](const Vec3& nn, const Vec3& view, const LtcTexel& t, double alpha) {
          return in.scalar("sphere_light_ltc_cv", Args().geometry(nn, view, nn)
                                                      << alpha << t.norm << t.m00 << t.m02 << t.m20 << t.m22
                                                      << sphere.toCenter << R);
        },
        [&](const Vec3& nn, const Vec3& view, const LtcTexel& t, double alpha) {
          return in.scalar("sphere_light_ltc_sheen", Args().geometry(nn, view, nn)
                                                         << alpha << t.norm << t.m00 << t.m02 << t.m20 << t.m22
                                                         << sphere.toCenter << R);
        });
  });
}

Vec3 shadeTube(const ModelEvalInput& in, const Pixel& px, const TubeLight& tube) {
  if (!in.bound("tube_light_ltc_cv")) return shadeTubeRepresentative(in, px, tube);
  const Vec3 n = in.frame.n, v = in.frame.v;
  const Vec3 L0 = tube.toStart, L1 = tube.toEnd, axis = L1 - L0;
  const double R = tube.radius, len = length(axis);
  const Vec3 P = tubeEquivalentPoint(n, L0, L1);
  const double dEq = length(P);
  const double area = kPi * R * R + 2.0 * R * len;
  const double size = std::sqrt(area / kPi);
  const double dLight = std::max(dEq, size / kMaxSinAlpha);
  const double t = len > 0.0 ? std::clamp(-dot(L0, axis) / (len * len), 0.0, 1.0) : 0.0;
  const double h = length(L0 + axis * t);
  const double clear = R > 0.0 ? std::clamp(h / R - 1.0, 0.0, 1.0) : 0.0;
  const double w = dLight > 0.0 ? ltcBlend(size / dLight) * clear : 0.0;
  const Vec3 rp = w < 1.0 ? shadeTubeRepresentative(in, px, tube) : Vec3{0.0, 0.0, 0.0};
  return blend(rp, w, [&] {
    const Vec3 l = dEq > 0.0 ? P / dEq : n;
    const double falloff = in.scalar("light_falloff", Args() << l * dLight << tube.falloffRadius);
    const Vec3 luminance = tube.intensity * (falloff * dLight * dLight / area);
    return ltcLight(
        in, px, P, luminance,
        [&](const Vec3& nn) {
          return in.scalar("tube_light_ltc", Args().geometry(nn, v, nn) << 1.0 << 0.0 << 0.0 << 1.0 << L0 << L1 << R);
        },
        [&](const Vec3& nn, const Vec3& view, const LtcTexel& tx, double alpha) {
          return in.scalar("tube_light_ltc_cv", Args().geometry(nn, view, nn) << alpha << tx.norm << tx.m00 << tx.m02
                                                                              << tx.m20 << tx.m22 << L0 << L1 << R);
        },
        [&](const Vec3& nn, const Vec3& view, const LtcTexel& tx, double alpha) {
          return in.scalar("tube_light_ltc_sheen", Args().geometry(nn, view, nn) << alpha << tx.norm << tx.m00 << tx.m02
                                                                                 << tx.m20 << tx.m22 << L0 << L1 << R);
        });
  });
}

Vec3 shadeRect(const ModelEvalInput& in, const Pixel& px, const RectLight& rect) {
  return shadePlanar(in, px, rect, "rect_light_ltc", "rect_light_ltc_cv", "rect_light_ltc_sheen");
}

Vec3 shadeDisk(const ModelEvalInput& in, const Pixel& px, const DiskLight& disk) {
  return shadePlanar(in, px, disk, "disk_light_ltc", "disk_light_ltc_cv", "disk_light_ltc_sheen");
}

}  // namespace mb::ref::standard
