// The brick library as data: slots (shared signatures), bricks (GLSL + citation + domain +
// tolerance) and shading models (skeleton + inputs), read from shaderlib/manifest.json.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"
#include "core/environment_mode.hpp"
#include "core/light_type.hpp"
#include "core/value_type.hpp"

namespace mb {

// What kind of roughness an input is (slot.json params' and model inputs' "roughness"): at
// fp16 such an input starts at Filament's floor (validate/precision_domain.hpp). Probes name
// their inputs, so the kind belongs to the name: every input of one name says the same.
enum class RoughnessKind { None, Perceptual, Alpha };
const std::vector<std::string>& roughnessKindNames();  // perceptual, alpha

struct SlotParam {
  std::string name;
  ValueType type;
  RoughnessKind roughness = RoughnessKind::None;
};

// A role in a lobe. All bricks of a slot share `returns` and `params`.
struct Slot {
  std::string name;
  std::string description;
  ValueType returns = ValueType::Float;
  std::vector<SlotParam> params;
  // slot.json "energy": the part its bricks play in the energy checks (compiler/energy/):
  // "distribution" (D), "visibility" (V) or "diffuse"; empty when they play none. Every
  // brick of such a slot carries an "energy" entry (BrickEnergy).
  std::string energyRole;
};

// Inclusive range of a scalar probe input, or of each component of a vector input.
struct Range {
  double lo = 0.0;
  double hi = 1.0;
};

// Where the sampler may go for a Geometry input: n.v and n.l are drawn in these ranges.
struct GeometryDomain {
  Range NoV{1e-3, 1.0};
  Range NoL{0.0, 1.0};
};

struct Tolerance {
  double abs = 0.0;  // absolute part
  double rel = 0.0;  // relative part: pass when |gpu-ref| <= abs + rel*|ref|
  std::string reason;
};

// A brick's "energy" entry (docs/energy.md): what the energy checks integrate it with and
// what theory says about the result. The words are the loader's vocabulary (brickEnergy*
// below); compiler/energy/lobes.cpp turns them into lobes.
struct BrickEnergy {
  // Non-empty: the brick is left out of the energy checks, for this reason.
  std::string excluded;
  // "specular", "sheen", "anisotropic" (D and V bricks: a D pairs with V bricks of its lobe)
  // or "diffuse" (bricks of a diffuse slot).
  std::string lobe;
  // D bricks: the quadrature map that follows this D ("ggx", "beckmann", "charlie",
  // "ashikhmin"), and the V bricks it pairs with: every V of its lobe when `allVisibilities`,
  // else the listed ones.
  std::string halfVectorMap;
  bool allVisibilities = false;
  std::vector<std::string> visibilities;
  // V and diffuse bricks: "conserving" (albedo <= 1 by construction), "not_conserving" (known
  // to exceed 1) or "unbounded" (nothing guarantees <= 1), and why, with the source.
  std::string expectation;
  std::string note;
};
const std::vector<std::string>& brickEnergyRoles();         // distribution, visibility, diffuse
const std::vector<std::string>& brickEnergyLobes();         // specular, sheen, anisotropic
const std::vector<std::string>& brickEnergyMaps();          // ggx, beckmann, charlie, ashikhmin
const std::vector<std::string>& brickEnergyExpectations();  // conserving, not_conserving, unbounded

struct Brick {
  std::string id;
  std::string slot;
  std::string file;      // relative to the shaderlib root, e.g. "specular_d/d_ggx.glsl"
  std::string function;  // GLSL function name defined in `file`
  std::string name;      // human-readable name
  std::string citation;  // paper / seed the formula comes from
  // Other GLSL units (ids of "units") it needs. Manifest key "requires"; renamed here because
  // `requires` is a C++20 keyword.
  std::vector<std::string> requiredUnits;
  std::map<std::string, Range> domain;  // per scalar/vector param
  GeometryDomain geometry;
  Tolerance tolerance;
  std::string notes;  // precision notes
  // Manifest "truth_note": where the brick's ground truth (MB_GROUND_TRUTH) is not its slot's
  // exact quantity, what it is instead, as bench's tables print it ("truth at f0 = 0.04" for a
  // brick that assumes f0); empty otherwise.
  std::string truthNote;
  // Optional: the numerically naive form a stability fix replaced (same function name), and
  // what goes wrong with it. Validation of it shows the problem; it is never emitted into
  // permutations.
  std::string unstableFile;
  std::string unstableProblem;
  // Manifest "fp16_twin": the brick of the same slot that replaces this one in fp16
  // permutations (emit/precision.hpp brickForPrecision), or empty when the brick is kept.
  std::string fp16Twin;
  BrickEnergy energy;  // manifest "energy"; meaningful when the slot has an energyRole
  // Manifest "kernel_roles": the parts the brick plays in the library's own kernels (the DFG
  // LUT's, the environment prefilter's), which look their bricks up by role
  // (ShaderLibrary::brickForKernelRole), not by id.
  std::vector<std::string> kernelRoles;
};

// A role of brickKernelRoles(): the kernel that calls it, and the slot whose signature it
// calls it with (a brick of another slot cannot take the role).
struct KernelRole {
  std::string role;
  std::string slot;
  std::string kernel;
};
const std::vector<KernelRole>& brickKernelRoles();

// Shared GLSL that is not a brick (common helpers).
struct Unit {
  std::string id;
  std::string file;
};

struct ModelInput {
  std::string name;  // name in material JSON and in the MaterialInputs struct
  ValueType type = ValueType::Float;
  std::vector<double> defaultValue;
  Range range;
  std::string description;
  std::string feature;          // non-empty: exists only when this feature is enabled
  std::vector<double> neutral;  // value at which the feature changes nothing (or empty)
  RoughnessKind roughness = RoughnessKind::None;
};

// One brick call of a skeleton (docs/models.md "Roles"): MB_SLOT_<role>, filled by a brick
// of `slot`. Conditions say in which permutations the role exists.
struct ModelRole {
  std::string role;
  std::string slot;
  std::string defaultBrick;                   // empty: every material must choose
  std::string feature;                        // non-empty: only with this feature enabled
  std::vector<LightType> lights;              // non-empty: only with one of these light types
  std::vector<EnvironmentMode> environments;  // non-empty: only in one of these modes
  // Non-empty: only where one of `lights` is shaded by this method (the model's lightMethods);
  // every light of the role then offers it.
  std::string method;
  // How much more than the light's irradiance (or the environment's radiance) multiplies the
  // role's result in the composition, >= 1: validation scales the bound brick's absolute
  // tolerance by it (validate/probe_program.hpp compositionTolerance), for `toleranceReason`.
  double toleranceScale = 1.0;
  std::string toleranceReason;
  std::string description;
};

// How a model may shade one light type, when it offers more than one way (manifest
// "lightMethods", docs/models.md "Light methods"): a material picks one (its "lightMethods"),
// else a quality level's choice, else the default. Roles with a "method" exist only where
// their light is shaded by that method, so the choice is made before code generation.
struct LightMethodChoice {
  LightType light = LightType::Dir;
  std::vector<std::string> methods;            // as listed
  std::string defaultMethod;                   // at "high" and wherever `quality` is silent
  std::map<std::string, std::string> quality;  // level name ("low", "medium") -> method
  std::string description;
};

// An optional layer of a model: a GLSL fragment the skeleton calls under MB_FEATURE_<NAME>.
struct ModelFeature {
  std::string name;
  std::string description;
  std::string file;  // GLSL relative to the shaderlib root, or empty
  std::vector<std::string> requiredUnits;
};

// A combination of bricks that makes no sense in a model (manifest "incompatible"): a
// permutation in which every listed role is active and bound to the listed brick is invalid
// (permute/axes.hpp invalidReason), for `reason`.
struct BrickRule {
  std::vector<std::pair<std::string, std::string>> bricks;  // role -> brick id, as listed
  std::string reason;
};

struct ShadingModel {
  std::string name;
  std::string description;
  std::string skeleton;                       // GLSL file relative to the shaderlib root
  std::vector<std::string> parts;             // more skeleton files, included after it, in order
  std::vector<std::string> requiredUnits;     // units (manifest key "requires")
  std::vector<LightType> lights;              // light types the skeleton shades, in manifest order
  std::vector<EnvironmentMode> environments;  // environment modes it supports, in manifest order
  std::vector<ModelFeature> features;
  std::vector<ModelRole> roles;
  std::vector<ModelInput> inputs;  // core inputs, then feature inputs, as listed
  // Manifest "quality": level ("low", "medium") -> role -> brick that replaces the role's
  // default at that level (docs/scenes.md "Quality"). "high" is the default bindings; a level
  // absent here is not defined by the model (permute/axes.hpp invalidReason).
  std::map<std::string, std::map<std::string, std::string>> quality;
  std::vector<BrickRule> incompatible;
  std::vector<LightMethodChoice> lightMethods;  // in manifest order

  const ModelRole* findRole(const std::string& role) const;
  const ModelFeature* findFeature(const std::string& feature) const;
  const LightMethodChoice* findLightMethod(LightType light) const;
  // Roles a material always has (no condition): the old "slots" of the model.
  std::vector<std::string> coreRoles() const;
};

// The bricks glTF import binds (shaderlib/gltf_defaults.json, docs/formats.md): the glTF
// spec's BRDF where the model's defaults are the seed's or where the model leaves the choice
// to the material. Data, so that a brick taking one of these roles changes no C++.
struct GltfBinding {
  std::string role;
  std::string brick;
};
struct GltfDefaults {
  std::string file;                 // relative to the shaderlib root; empty when the library declares none
  std::string model;                // the model every glTF material maps to
  std::vector<GltfBinding> always;  // bound for every material, in file order
  // Feature -> bound when a material enables it (its glTF extension is present).
  std::map<std::string, std::vector<GltfBinding>> features;
};

class ShaderLibrary {
 public:
  // Reads `<root>/manifest.json`; throws DiagnosticError with file:line:col on bad data.
  static ShaderLibrary load(const std::filesystem::path& root);
  // The default root: $MATBRICKS_SHADERLIB, else dataRoot()/shaderlib (installed beside the
  // program, or the source tree's; core/data_dir.hpp).
  static std::filesystem::path defaultRoot();

  const std::filesystem::path& root() const { return root_; }
  const std::vector<Slot>& slots() const { return slots_; }
  const std::vector<Brick>& bricks() const { return bricks_; }
  const std::vector<ShadingModel>& models() const { return models_; }
  const std::vector<Unit>& units() const { return units_; }

  const Slot* findSlot(const std::string& name) const;
  const Brick* findBrick(const std::string& id) const;
  const ShadingModel* findModel(const std::string& name) const;
  const Unit* findUnit(const std::string& id) const;
  std::vector<std::string> brickIds() const;
  std::vector<std::string> bricksOfSlot(const std::string& slot) const;
  // The kind of the slot parameters and model inputs called `inputName` (None for any other
  // name; the loader checks that inputs of one name agree).
  RoughnessKind roughnessKind(const std::string& inputName) const;
  // The brick that takes a kernel role (brickKernelRoles), or nullptr.
  const Brick* brickForKernelRole(const std::string& role) const;
  const std::map<std::string, RoughnessKind>& roughnessKinds() const { return roughnessKinds_; }
  // Manifest "gltf_defaults" (empty file and model when the library declares none).
  const GltfDefaults& gltfDefaults() const { return gltfDefaults_; }

  // Reads a file under the root (cached). Throws DiagnosticError if missing.
  const std::string& source(const std::string& relativeFile) const;
  // Display path used in #line directives and diagnostics: "shaderlib/<file>".
  static std::string displayPath(const std::string& relativeFile);

 private:
  std::filesystem::path root_;
  std::vector<Slot> slots_;
  std::vector<Brick> bricks_;
  std::vector<ShadingModel> models_;
  std::vector<Unit> units_;
  std::map<std::string, RoughnessKind> roughnessKinds_;  // only inputs with a kind
  GltfDefaults gltfDefaults_;
  mutable std::map<std::string, std::string> sources_;
};

}  // namespace mb
