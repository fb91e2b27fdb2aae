// Reference compositions of shading models: plain C++ in double that combines the
// references of whichever bricks a material bound to the model's roles (docs/models.md).
#pragma once
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/reference.hpp"

namespace mb::ref {

// The same structs as shaderlib/common/lights.glsl, in double. Positions are relative to
// the shading point; intensities are luminous intensities (colour times candela).
struct ShadingFrame {
  Vec3 n, v, ng, t;  // unit: shading normal, view, geometric normal, tangent
};
struct DirectionalLight {
  Vec3 l, illuminance;
};
struct PointLight {
  Vec3 toLight, intensity;
  double falloffRadius = 0;
};
struct SpotLight {
  Vec3 toLight, axis, intensity;
  double falloffRadius = 0, cosOuter = 0, cosInner = 0;
};
struct SphereLight {
  Vec3 toCenter;
  double radius = 0;
  Vec3 intensity;
  double falloffRadius = 0;
};
struct TubeLight {
  Vec3 toStart, toEnd;
  double radius = 0;
  Vec3 intensity;
  double falloffRadius = 0;
};
struct Environment {
  std::string mode;  // "sh", "ibl_lut", "ibl_analytic"
  Vec3 sh[9];
  double ao = 1, maxMip = 8;
  Vec3 prefiltered;  // the probe's fetched radiance before shaping
  Vec3 dfg;          // the probe's DFG LUT texel (ibl_lut)
  // Real texture fetches (the preview's reference render, compiler/preview/): when set, they
  // stand for the fragment shader's mb_fetch_prefiltered (textureLod of the prefiltered cube)
  // and mb_fetch_dfg (the DFG LUT texel at (NoV, perceptual roughness)), and `prefiltered` and
  // `dfg` are unused. Unset (validation's probe), the probe's record values are used.
  std::function<Vec3(const Vec3& r, double lod)> fetchPrefiltered;
  std::function<Vec3(double NoV, double perceptualRoughness)> fetchDfg;
  // mb_fetch_prefiltered: fetchPrefiltered, else the probe's prefiltered * shape(r, lod)
  // (probe_scene.glsl).
  Vec3 prefilteredAt(const Vec3& r, double lod) const;
  // mb_fetch_dfg: fetchDfg, else the probe's texel `dfg` (the same for every lookup).
  Vec3 dfgAt(double NoV, double perceptualRoughness) const {
    return fetchDfg ? fetchDfg(NoV, perceptualRoughness) : dfg;
  }
  bool ibl() const { return mode == "ibl_lut" || mode == "ibl_analytic"; }
};
// The probe's smooth known function of direction and mip level (probe_scene.glsl).
double probeEnvironmentShape(const Vec3& r, double lod);

// Arguments of one brick call, packed in slot-signature order.
class Args {
 public:
  Args& operator<<(double x) {
    values.push_back(x);
    return *this;
  }
  Args& operator<<(const Vec3& v) {
    // Three push_backs, not insert({...}): GCC 12 reports a false -Wstringop-overflow for the
    // inlined initializer-list insert.
    values.push_back(v.x);
    values.push_back(v.y);
    values.push_back(v.z);
    return *this;
  }
  // A Geometry parameter: the vectors it is built from (makeGeometry normalizes them).
  Args& geometry(const Vec3& n, const Vec3& v, const Vec3& l) { return *this << n << v << l; }
  std::vector<double> values;
};

struct ModelEvalInput {
  ShadingFrame frame;
  std::set<std::string> features;
  std::optional<DirectionalLight> dir;
  std::optional<PointLight> point;
  std::optional<SpotLight> spot;
  std::optional<SphereLight> sphere;
  std::optional<TubeLight> tube;
  std::optional<Environment> env;

  std::map<std::string, std::vector<double>> inputs;  // model input name -> value
  std::map<std::string, std::string> bricks;          // role -> brick id
  // Call each bound brick's ground truth where one is registered (else its reference): the
  // exact material a permutation approximates, which bench measures error against.
  bool groundTruths = false;

  bool has(const std::string& feature) const { return features.count(feature) != 0; }
  bool bound(const std::string& role) const { return bricks.count(role) != 0; }
  double floatInput(const std::string& name) const;
  Vec3 vec3Input(const std::string& name) const;
  // Evaluates the reference of the brick bound to `role`.
  double scalar(const std::string& role, const Args& args) const;
  Vec3 vec3(const std::string& role, const Args& args) const;
};

// max(x, 0) per component: the models clamp the SH irradiance, which a truncated expansion
// can ring below 0, as Filament's Irradiance_SphericalHarmonics does.
inline Vec3 nonNegative(const Vec3& x) { return {x.x > 0.0 ? x.x : 0.0, x.y > 0.0 ? x.y : 0.0, x.z > 0.0 ? x.z : 0.0}; }

using ModelReferenceFn = Vec3 (*)(const ModelEvalInput&);

class ModelRegistry {
 public:
  static ModelRegistry& instance();
  bool add(const std::string& model, ModelReferenceFn fn);
  ModelReferenceFn find(const std::string& model) const;

 private:
  std::map<std::string, ModelReferenceFn> entries_;
};

}  // namespace mb::ref

#define MB_MODEL_REFERENCE(NAME, FN)                                            \
  [[maybe_unused]] static const bool MB_CONCAT(mb_model_reference_, __LINE__) = \
      ::mb::ref::ModelRegistry::instance().add(NAME, FN)
