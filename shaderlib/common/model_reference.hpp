// Reference compositions of shading models: plain C++ in double that combines the
// references of whichever bricks a material bound to the model's roles (docs/models.md).
#pragma once
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
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
// Rectangle and disk lights: centre, half-edge (semi-axis) vectors, luminance; one-sided, emitting
// on the side of cross(halfX, halfY).
struct RectLight {
  Vec3 toCenter, halfX, halfY, luminance;
};
struct DiskLight {
  Vec3 toCenter, halfX, halfY, luminance;
};
// One entry of an LTC table (shaderlib/ltc/ggx.json, or the sheen's charlie.json): M^-1's stored
// elements and the lobe's magnitudes, as mb_fetch_ltc_matrix / mb_fetch_ltc_magnitude (or their
// _sheen_ twins) return them.
struct LtcTexel {
  double m00 = 1, m02 = 0, m20 = 0, m22 = 1;
  double norm = 1, fresnel = 0;
};
// Which of the library's LTC tables a lookup reads.
enum class LtcLobe { Specular, Sheen };
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

// Arguments of one brick call, packed in slot-signature order. Held inline (no allocation):
// a brick call is made several times per light per evaluation.
class Args {
 public:
  static constexpr size_t kCapacity = 32;  // the longest slot signature packs 15 doubles
  Args& operator<<(double x) {
    if (size_ == kCapacity) overflow();
    values_[size_++] = x;
    return *this;
  }
  Args& operator<<(const Vec3& v) { return *this << v.x << v.y << v.z; }
  // A Geometry parameter: the vectors it is built from (makeGeometry normalizes them).
  Args& geometry(const Vec3& n, const Vec3& v, const Vec3& l) { return *this << n << v << l; }
  const double* data() const { return values_; }
  size_t size() const { return size_; }

 private:
  [[noreturn]] static void overflow();
  double values_[kCapacity];
  size_t size_ = 0;
};

// The names the reference compositions use, as compile-time indices: a role, model input or
// feature named by a string literal becomes its index in these tables at compile time (a name
// missing from its table does not compile), so a resolved ModelEvalInput finds a brick or an
// input by index instead of by string.
namespace names {
inline constexpr std::string_view kRoles[] = {"anisotropy_alpha",
                                              "bent_normal_aniso",
                                              "clearcoat_base_roughness",
                                              "clearcoat_d",
                                              "clearcoat_fresnel",
                                              "clearcoat_v",
                                              "dfg_lut",
                                              "diffuse",
                                              "disk_light_ltc",
                                              "disk_light_ltc_cv",
                                              "disk_light_ltc_sheen",
                                              "diffuse_wrap",
                                              "energy_compensation",
                                              "env_brdf",
                                              "f0_clearcoat",
                                              "fresnel",
                                              "light_falloff",
                                              "mip_mapping",
                                              "rect_light_ltc",
                                              "rect_light_ltc_cv",
                                              "rect_light_ltc_sheen",
                                              "roughness",
                                              "sh_irradiance",
                                              "sheen_d",
                                              "sheen_v",
                                              "specular_d",
                                              "specular_d_aniso",
                                              "specular_occlusion",
                                              "specular_v",
                                              "specular_v_aniso",
                                              "sphere_energy_normalization",
                                              "sphere_horizon_wrap",
                                              "sphere_light_ltc",
                                              "sphere_light_ltc_cv",
                                              "sphere_light_ltc_sheen",
                                              "sphere_light_point",
                                              "tube_energy_normalization",
                                              "tube_light_ltc",
                                              "tube_light_ltc_cv",
                                              "tube_light_ltc_sheen",
                                              "tube_light_point"};
inline constexpr std::string_view kInputs[] = {
    "ambientOcclusion", "anisotropy", "baseColor", "clearCoat",  "clearCoatNormal", "clearCoatRoughness", "emissive",
    "f0Dielectric",     "metallic",   "roughness", "sheenColor", "sheenRoughness",  "subsurfaceColor",    "wrap"};
inline constexpr std::string_view kFeatures[] = {"anisotropy", "clearcoat", "sheen"};

template <size_t N>
consteval int indexIn(const std::string_view (&table)[N], std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (table[i] == name) return static_cast<int>(i);
  throw "name missing from its table in common/model_reference.hpp";  // not a constant: no compile
}
// Runtime lookup, for building a plan: -1 when the name is not in the table.
template <size_t N>
int find(const std::string_view (&table)[N], std::string_view name) {
  for (size_t i = 0; i < N; ++i)
    if (table[i] == name) return static_cast<int>(i);
  return -1;
}

template <const auto& Table>
struct Name {
  consteval Name(const char* s) : text(s), index(indexIn(Table, text)) {}  // NOLINT: implicit by design
  std::string_view text;
  int index;
};
}  // namespace names
using RoleName = names::Name<names::kRoles>;
using InputName = names::Name<names::kInputs>;
using FeatureName = names::Name<names::kFeatures>;

// A float or vec3 model input held inline.
struct InputValue {
  double v[3] = {0, 0, 0};
  int size = 0;  // 0: not set
};

struct ModelEvalInput {
  ShadingFrame frame;
  std::set<std::string> features;
  std::optional<DirectionalLight> dir;
  std::optional<PointLight> point;
  std::optional<SpotLight> spot;
  std::optional<SphereLight> sphere;
  std::optional<TubeLight> tube;
  std::optional<RectLight> rect;
  std::optional<DiskLight> disk;
  std::optional<Environment> env;
  // The LTC tables' fetches (the area lights shaded by LTC): fetchLtc when set (the preview's
  // reference render reads the tables as the fragment shader does), else the probe's record
  // texels `ltc` and `sheenLtc`, the same for every lookup.
  LtcTexel ltc, sheenLtc;
  std::function<LtcTexel(LtcLobe lobe, double NoV, double perceptualRoughness)> fetchLtc;
  LtcTexel ltcAt(double NoV, double perceptualRoughness) const {
    return fetchLtc ? fetchLtc(LtcLobe::Specular, NoV, perceptualRoughness) : ltc;
  }
  LtcTexel sheenLtcAt(double NoV, double perceptualRoughness) const {
    return fetchLtc ? fetchLtc(LtcLobe::Sheen, NoV, perceptualRoughness) : sheenLtc;
  }

  std::map<std::string, std::vector<double>> inputs;  // model input name -> value
  std::map<std::string, std::string> bricks;          // role -> brick id
  // Call each bound brick's ground truth where one is registered (else its reference): the
  // exact material a permutation approximates, which bench measures error against.
  bool groundTruths = false;

  // Looks up, once, each role's reference (or ground truth), each input's value and the
  // features, from `bricks`, `inputs`, `features` and `groundTruths`: from then on the
  // accessors below read the resolved plan, by index, and `bricks`, `inputs` and `features`
  // are no longer read (set per-record inputs with setInput). The results are those of the
  // unresolved path, which looks every name up per call.
  void resolve();
  bool resolved() const { return resolved_; }
  // Sets a model input (`size` doubles) of a resolved input; an index from
  // names::find(names::kInputs, name).
  void setInput(int index, const double* value, int size) {
    InputValue& slot = plan_.inputs[index];
    for (int k = 0; k < size; ++k) slot.v[k] = value[k];
    slot.size = size;
  }

  bool has(FeatureName feature) const {
    return resolved_ ? (plan_.features >> feature.index & 1u) != 0 : features.count(std::string(feature.text)) != 0;
  }
  bool bound(const std::string& role) const { return bricks.count(role) != 0; }
  double floatInput(InputName name) const {
    if (resolved_ && plan_.inputs[name.index].size == 1) return plan_.inputs[name.index].v[0];
    return floatInputByName(std::string(name.text));
  }
  Vec3 vec3Input(InputName name) const {
    if (resolved_ && plan_.inputs[name.index].size == 3) {
      const double* v = plan_.inputs[name.index].v;
      return {v[0], v[1], v[2]};
    }
    return vec3InputByName(std::string(name.text));
  }
  // Evaluates the reference of the brick bound to `role`.
  double scalar(RoleName role, const Args& args) const {
    double out = 0;
    reference(role).eval(args.data(), &out);
    return out;
  }
  Vec3 vec3(RoleName role, const Args& args) const {
    double out[3] = {0, 0, 0};
    reference(role).eval(args.data(), out);
    return {out[0], out[1], out[2]};
  }

 private:
  struct Plan {
    const Reference* roles[std::size(names::kRoles)] = {};
    InputValue inputs[std::size(names::kInputs)];
    uint32_t features = 0;
  };
  const Reference& reference(RoleName role) const {
    if (resolved_ && plan_.roles[role.index]) return *plan_.roles[role.index];
    return referenceByName(std::string(role.text));
  }
  // The unresolved path (and the resolved one's errors: a missing input or brick throws).
  double floatInputByName(const std::string& name) const;
  Vec3 vec3InputByName(const std::string& name) const;
  const Reference& referenceByName(const std::string& role) const;

  bool resolved_ = false;
  Plan plan_;
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

#define MB_MODEL_REFERENCE(NAME, FN)                                               \
  [[maybe_unused]] static const bool MB_CONCAT(mb_model_reference_, __COUNTER__) = \
      ::mb::ref::ModelRegistry::instance().add(NAME, FN)
