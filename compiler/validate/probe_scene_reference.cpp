#include "validate/probe_scene_reference.hpp"

#include <cmath>
#include <stdexcept>

namespace mb {
namespace {

using ref::Vec3;

// lights.glsl's mb_orthonormal_basis (Duff et al. 2017), in double.
void orthonormalBasis(const Vec3& n, Vec3& t, Vec3& b) {
  double s = n.z >= 0.0 ? 1.0 : -1.0;
  double a = -1.0 / (s + n.z);
  double c = n.x * n.y * a;
  t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

class Record {
 public:
  Record(const ProbeLayout& layout, const double* data) : layout_(layout), data_(data) {}
  double scalar(const std::string& name) const { return data_[at(name)]; }
  Vec3 vec3(const std::string& name) const {
    uint32_t o = at(name);
    return {data_[o], data_[o + 1], data_[o + 2]};
  }

 private:
  uint32_t at(const std::string& name) const {
    const ProbeInput* in = layout_.find(name);
    if (!in) throw std::logic_error("probe record has no input '" + name + "'");
    return in->offset;
  }
  const ProbeLayout& layout_;
  const double* data_;
};

}  // namespace

void sceneFromRecord(const ProbeScene& scene, const ProbeLayout& layout, const double* record,
                     ref::ModelEvalInput& in) {
  Record r(layout, record);
  ref::ShadingFrame& f = in.frame;
  f.n = ref::normalize(r.vec3("n"));
  f.v = ref::normalize(r.vec3("v"));
  Vec3 t0, b0;
  orthonormalBasis(f.n, t0, b0);
  if (scene.fullFrame) {
    f.ng = ref::normalize(f.n + b0 * r.scalar("ngTilt"));
    double a = r.scalar("tangentAngle");
    f.t = t0 * std::cos(a) + b0 * std::sin(a);
  } else {
    f.ng = f.n;
    f.t = t0;
  }
  const Vec3 lu = ref::normalize(r.vec3("l"));
  Vec3 lt, lb;
  orthonormalBasis(lu, lt, lb);
  for (const auto& type : scene.lights) {
    if (type == "dir") {
      in.dir = ref::DirectionalLight{lu, scene.illuminanceInput ? r.vec3("illuminance") : Vec3{1, 1, 1}};
    } else if (type == "point") {
      in.point =
          ref::PointLight{lu * r.scalar("pointDistance"), r.vec3("pointIntensity"), r.scalar("pointFalloffRadius")};
    } else if (type == "spot") {
      double a = r.scalar("spotAxisAngle"), cosOuter = r.scalar("spotCosOuter");
      Vec3 axis = lt * std::sin(a) - lu * std::cos(a);
      double cosInner = cosOuter + r.scalar("spotInnerFraction") * (1.0 - cosOuter);
      in.spot = ref::SpotLight{lu * r.scalar("spotDistance"), axis,     r.vec3("spotIntensity"),
                               r.scalar("spotFalloffRadius"), cosOuter, cosInner};
    } else if (type == "sphere") {
      double d = r.scalar("sphereDistance");
      in.sphere = ref::SphereLight{lu * d, r.scalar("sphereRadiusFraction") * d, r.vec3("sphereIntensity"),
                                   r.scalar("sphereFalloffRadius")};
    } else if (type == "tube") {
      double a = r.scalar("tubeAxisAngle"), d = r.scalar("tubeDistance");
      Vec3 axis = ref::normalize(lt * std::cos(a) + lb * std::sin(a) + lu * r.scalar("tubeAxisTilt"));
      Vec3 center = lu * d, halfSegment = axis * (r.scalar("tubeHalfLengthFraction") * d);
      in.tube = ref::TubeLight{center - halfSegment, center + halfSegment, r.scalar("tubeRadiusFraction") * d,
                               r.vec3("tubeIntensity"), r.scalar("tubeFalloffRadius")};
    }
  }
  if (scene.environment == "none") return;
  ref::Environment env;
  env.mode = scene.environment;
  for (int i = 0; i < 9; ++i) env.sh[i] = r.vec3("sh" + std::to_string(i));
  env.ao = r.scalar("ao");
  env.maxMip = kProbeMaxMip;
  env.prefiltered = env.ibl() ? r.vec3("prefiltered") : Vec3{};
  env.dfg = scene.environment == "ibl_lut" ? Vec3{r.scalar("dfgX"), r.scalar("dfgY"), r.scalar("dfgZ")} : Vec3{0, 1, 0};
  in.env = env;
}

}  // namespace mb
