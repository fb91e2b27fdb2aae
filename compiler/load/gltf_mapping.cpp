// One glTF material -> MaterialSource of the `standard` model (docs/gltf.md has the table).
// Factors use the glTF defaults, not the model's (glTF's metallicFactor defaults to 1, the
// model's metallic to 0), so every input the glTF material defines is written explicitly.
// A texture becomes a user parameter holding the sampled texel, and one line of generated
// surface code applies the combination the glTF spec defines for it.
#include <algorithm>
#include <cctype>
#include <optional>

#include "core/glsl_float.hpp"
#include "load/gltf_mapping.hpp"
#include "load/material_resolve.hpp"  // clipped

namespace mb::gltf {

using nlohmann::json;

namespace {

const char* kClearcoat = "KHR_materials_clearcoat";
const char* kSheen = "KHR_materials_sheen";
const char* kAnisotropy = "KHR_materials_anisotropy";
const char* kSpecular = "KHR_materials_specular";
const char* kIor = "KHR_materials_ior";
const char* kEmissiveStrength = "KHR_materials_emissive_strength";
const char* kTextureTransform = "KHR_texture_transform";

std::string vec3Literal(const std::vector<double>& v) {
  return "vec3(" + glslFloat(v[0], FloatDigits::Nine) + ", " + glslFloat(v[1], FloatDigits::Nine) + ", " +
         glslFloat(v[2], FloatDigits::Nine) + ")";
}

class MaterialMapper {
 public:
  MaterialMapper(JsonFields& f, const FileContext& ctx, size_t index)
      : f_(f), ctx_(ctx), ptr_(JsonFields::element("/materials", index)) {
    out_.index = static_cast<int>(index);
    out_.source.file = ctx.file;
    out_.source.form = "gltf";
    where_ = f_.valueAt(ptr_);
  }

  GltfMaterial run(std::set<std::string>& usedExtensions) {
    MaterialSource& s = out_.source;
    s.model = {ctx_.defaults.model, where_};
    for (const auto& b : ctx_.defaults.always) s.bricks.push_back({{b.role, where_}, {b.brick, where_}});
    if (!f_.isObject(ptr_)) return out_;
    out_.gltfName = f_.string(JsonFields::member(ptr_, "name")).value_or("");
    readExtensionsUsed(usedExtensions);
    readMetallicRoughness();
    readOcclusionAndNormal();
    readEmissive();
    readAlpha();
    if (has(kClearcoat)) readClearcoat();
    if (has(kSheen)) readSheen();
    if (has(kAnisotropy)) readAnisotropy();
    if (has(kSpecular) || has(kIor)) readSpecular();
    finishSurface();
    return out_;
  }

 private:
  // --- reading -------------------------------------------------------------------------

  std::string at(const std::string& ptr, const std::string& key) const { return JsonFields::member(ptr, key); }
  std::string ext(const char* name) const { return at(at(ptr_, "extensions"), name); }
  bool has(const char* name) const { return present_.count(name) != 0; }

  double number(const std::string& ptr, double fallback) { return f_.number(ptr).value_or(fallback); }

  // An array of exactly `n` numbers, or `fallback` (absent, or reported when malformed).
  std::vector<double> numbers(const std::string& ptr, size_t n, std::vector<double> fallback) {
    const json* j = f_.find(ptr);
    if (!j) return fallback;
    if (!j->is_array() || j->size() != n ||
        !std::all_of(j->begin(), j->end(), [](const json& x) { return x.is_number(); })) {
      std::string expected = "an array of " + std::to_string(n) + " numbers";
      if (!j->is_array()) {
        f_.typeError(ptr, expected);
      } else {
        f_.error("E-FIELD-TYPE", f_.valueAt(ptr),
                 "'" + JsonFields::describe(ptr) + "' must be " + expected + ", found " +
                     (j->size() != n ? std::to_string(j->size()) + " value(s)" : "a value that is not a number"));
      }
      return fallback;
    }
    std::vector<double> out;
    for (const auto& x : *j) out.push_back(x.get<double>());
    return out;
  }

  // A non-negative integer (an index or a texCoord set), or nullopt (absent or reported).
  std::optional<int> index(const std::string& ptr) {
    const json* j = f_.find(ptr);
    if (!j) return std::nullopt;
    if (!j->is_number_integer() || j->get<long long>() < 0 || j->get<long long>() > 1 << 30) {
      f_.error("E-FIELD-TYPE", f_.valueAt(ptr),
               "'" + JsonFields::describe(ptr) + "' must be a non-negative integer, found " + clipped(j->dump()));
      return std::nullopt;
    }
    return static_cast<int>(j->get<long long>());
  }

  SourceLocation whereOf(const std::string& ptr) const { return f_.find(ptr) ? f_.valueAt(ptr) : where_; }

  void warn(std::string code, const SourceLocation& where, std::string message) {
    out_.source.warnings.push_back({Severity::Warning, std::move(code), where, std::move(message), ""});
  }

  std::string label() const {
    return "material " + std::to_string(out_.index) + (out_.gltfName.empty() ? "" : " '" + out_.gltfName + "'");
  }

  void readExtensionsUsed(std::set<std::string>& usedExtensions) {
    std::string e = at(ptr_, "extensions");
    if (!f_.isObject(e)) return;
    for (const auto& [name, value] : f_.find(e)->items()) {
      std::string p = at(e, name);
      if (isMaterialExtensionSupported(name)) {
        if (f_.isObject(p)) present_.insert(name);
        continue;
      }
      usedExtensions.insert(name);
      // A required one is already an error at extensionsRequired; one warning suffices.
      if (!ctx_.required.count(name))
        warn("W-GLTF-UNSUPPORTED-EXTENSION", f_.keyAt(p),
             label() + " uses extension '" + name + "', which matbricks does not support: it is ignored");
    }
  }

  // --- parameters ----------------------------------------------------------------------

  // `array`: the JSON array the vector was read from as is, so a range error points at the
  // offending number.
  void constant(const std::string& name, std::vector<double> value, const SourceLocation& where,
                const std::string& array = "") {
    SourceParam p;
    p.name = name;
    p.where = p.typeWhere = p.valueWhere = p.rangeWhere = where;
    if (!array.empty() && f_.find(array))
      for (size_t i = 0; i < value.size(); ++i) p.componentWhere.push_back(f_.valueAt(JsonFields::element(array, i)));
    p.type = value.size() == 3 ? "vec3" : "float";
    p.value = std::move(value);
    p.constant = true;
    out_.source.params.push_back(std::move(p));
  }

  // Reads the textureInfo at `ptr` (if present) into a texture input named `param` holding
  // `channels` of the texel; returns the GLSL expression of the input ("p.<param>" plus the
  // channel swizzle the surface code needs), or empty when absent or malformed.
  std::string texture(const std::string& ptr, const std::string& param, const std::string& channels, bool srgb,
                      const std::string& swizzle = "") {
    if (!f_.isObject(ptr)) return "";
    auto binding = textureBinding(ptr, param, channels, srgb);
    if (!binding) return "";
    out_.textures.push_back(*binding);
    if (param.empty()) return "";
    SourceParam p;
    p.name = param;
    p.where = p.typeWhere = p.valueWhere = p.rangeWhere = f_.valueAt(ptr);
    bool colour = channels == "rgb";
    p.type = colour ? "vec3" : "float";
    p.value = colour ? std::vector<double>{1.0, 1.0, 1.0} : std::vector<double>{1.0};
    p.range = Range{0.0, 1.0};
    out_.source.params.push_back(std::move(p));
    return "p." + param + swizzle;
  }

  std::optional<TextureBinding> textureBinding(const std::string& ptr, const std::string& param,
                                               const std::string& channels, bool srgb) {
    TextureBinding t;
    t.param = param;
    t.channels = channels;
    t.srgb = srgb;
    std::string indexPtr = at(ptr, "index");
    if (!f_.find(indexPtr)) {
      f_.error("E-MISSING-FIELD", f_.valueAt(ptr),
               "texture reference '" + JsonFields::describe(ptr) + "' is missing required field 'index'");
      return std::nullopt;
    }
    auto textureIndex = index(indexPtr);
    if (!textureIndex) return std::nullopt;
    if (static_cast<size_t>(*textureIndex) >= ctx_.textureCount) {
      f_.error("E-GLTF-INDEX", f_.valueAt(indexPtr),
               "texture index " + std::to_string(*textureIndex) + " is out of range: the file has " +
                   std::to_string(ctx_.textureCount) + " texture(s)");
      return std::nullopt;
    }
    t.texture = *textureIndex;
    t.texCoord = index(at(ptr, "texCoord")).value_or(0);
    t.scale = number(at(ptr, param == "occlusionTexture" ? "strength" : "scale"), 1.0);
    readTextureInfoExtensions(ptr, t);
    readImage(t);
    return t;
  }

  void readTextureInfoExtensions(const std::string& ptr, TextureBinding& t) {
    std::string e = at(ptr, "extensions");
    if (!f_.isObject(e)) return;
    for (const auto& [name, value] : f_.find(e)->items()) {
      if (name == kTextureTransform) {
        t.transform = true;
        readTextureTransform(at(e, name), t);
      } else if (!ctx_.required.count(name)) {
        warn("W-GLTF-UNSUPPORTED-EXTENSION", f_.keyAt(at(e, name)),
             label() + " uses texture extension '" + name + "', which matbricks does not support: it is ignored");
      }
    }
  }

  // KHR_texture_transform: offset [2], rotation (radians), scale [2], texCoord; the engine
  // applies them to the UVs, so they are kept for the manifest (issue 18).
  void readTextureTransform(const std::string& ptr, TextureBinding& t) {
    if (!f_.isObject(ptr)) return;
    std::vector<double> offset = numbers(at(ptr, "offset"), 2, {0.0, 0.0});
    std::vector<double> scale = numbers(at(ptr, "scale"), 2, {1.0, 1.0});
    t.offset[0] = offset[0];
    t.offset[1] = offset[1];
    t.uvScale[0] = scale[0];
    t.uvScale[1] = scale[1];
    t.rotation = number(at(ptr, "rotation"), 0.0);
    t.transformTexCoord = index(at(ptr, "texCoord")).value_or(-1);
  }

  void readImage(TextureBinding& t) {
    std::string tex = JsonFields::element("/textures", static_cast<size_t>(t.texture));
    if (!f_.isObject(tex)) return;
    std::string sourcePtr = at(tex, "source");
    auto image = index(sourcePtr);
    if (!image) return;
    if (static_cast<size_t>(*image) >= ctx_.imageCount) {
      f_.error("E-GLTF-INDEX", f_.valueAt(sourcePtr),
               "image index " + std::to_string(*image) + " is out of range: the file has " +
                   std::to_string(ctx_.imageCount) + " image(s)");
      return;
    }
    t.image = *image;
    std::string img = JsonFields::element("/images", static_cast<size_t>(*image));
    if (!f_.isObject(img)) return;
    if (auto uri = f_.string(at(img, "uri"))) {
      // Data URIs are long and say nothing an engine needs here.
      t.uri = uri->rfind("data:", 0) == 0 ? "(data uri)" : *uri;
    } else if (auto view = index(at(img, "bufferView"))) {
      t.uri = "bufferView " + std::to_string(*view);
    }
  }

  void line(std::string glsl) { surface_.push_back("  " + std::move(glsl)); }

  // --- the mapping (glTF 2.0 spec section 3.9, and one function per extension) ----------

  void readMetallicRoughness() {
    std::string pbr = at(ptr_, "pbrMetallicRoughness");
    if (f_.find(pbr) && !f_.isObject(pbr)) return;
    std::string bcPtr = at(pbr, "baseColorFactor");
    std::vector<double> bc = numbers(bcPtr, 4, {1, 1, 1, 1});
    alpha_ = bc[3];
    std::vector<double> rgb(bc.begin(), bc.begin() + 3);
    constant("baseColor", rgb, whereOf(bcPtr), bcPtr);
    std::string mPtr = at(pbr, "metallicFactor"), rPtr = at(pbr, "roughnessFactor");
    double metallic = number(mPtr, 1.0), roughness = number(rPtr, 1.0);
    constant("metallic", {metallic}, whereOf(mPtr));
    constant("roughness", {roughness}, whereOf(rPtr));

    std::string tex = texture(at(pbr, "baseColorTexture"), "baseColorTexture", "rgb", true);
    if (!tex.empty()) line("m.baseColor = " + vec3Literal(rgb) + " * " + tex + ";");
    // Metalness in B, roughness in G (glTF 2.0 spec, metallicRoughnessTexture).
    tex = texture(at(pbr, "metallicRoughnessTexture"), "metallicRoughnessTexture", "rgb", false);
    if (!tex.empty()) {
      line("m.metallic = " + glslFloat(metallic, FloatDigits::Nine) + " * " + tex + ".b;");
      line("m.roughness = " + glslFloat(roughness, FloatDigits::Nine) + " * " + tex + ".g;");
    }
  }

  void readOcclusionAndNormal() {
    std::string occ = at(ptr_, "occlusionTexture");
    std::string tex = texture(occ, "occlusionTexture", "r", false);
    // occluded = 1 + strength * (texel - 1) (glTF 2.0 spec, occlusionTextureInfo.strength).
    if (!tex.empty())
      line("m.ambientOcclusion = 1.0 + " + glslFloat(out_.textures.back().scale, FloatDigits::Nine) + " * (" + tex +
           " - 1.0);");
    // The normal map perturbs the shading frame's n, which the engine passes in.
    texture(at(ptr_, "normalTexture"), "", "rgb", false);
  }

  void readEmissive() {
    std::string ePtr = at(ptr_, "emissiveFactor");
    std::vector<double> e = numbers(ePtr, 3, {0, 0, 0});
    SourceLocation where = whereOf(ePtr);
    std::string array = ePtr;
    if (has(kEmissiveStrength)) {
      std::string sPtr = at(ext(kEmissiveStrength), "emissiveStrength");
      double strength = number(sPtr, 1.0);
      for (double& c : e) c *= strength;
      if (f_.find(sPtr)) {
        where = f_.valueAt(sPtr);  // a scaled value out of range is the strength's doing
        array.clear();
      }
    }
    std::string texPtr = at(ptr_, "emissiveTexture");
    if (!f_.find(ePtr) && !f_.find(texPtr)) return;  // the model's default is glTF's: none
    constant("emissive", e, where, array);
    std::string tex = texture(texPtr, "emissiveTexture", "rgb", true);
    if (!tex.empty()) line("m.emissive = " + vec3Literal(e) + " * " + tex + ";");
  }

  void readAlpha() {
    std::string modePtr = at(ptr_, "alphaMode");
    std::string mode = f_.string(modePtr).value_or("OPAQUE");
    out_.alphaMode = mode;
    out_.alphaCutoff = number(at(ptr_, "alphaCutoff"), 0.5);
    out_.doubleSided = f_.boolean(at(ptr_, "doubleSided")).value_or(false);
    if (mode != "OPAQUE" && mode != "MASK" && mode != "BLEND") {
      f_.error("E-FIELD-TYPE", f_.valueAt(modePtr),
               "'" + JsonFields::describe(modePtr) + "' must be 'OPAQUE', 'MASK' or 'BLEND', found '" + mode + "'",
               didYouMean(mode, {"OPAQUE", "MASK", "BLEND"}));
    } else if (mode != "OPAQUE" || alpha_ != 1.0) {
      warn("W-GLTF-NOT-SHADED",
           whereOf(mode != "OPAQUE" ? modePtr : at(at(ptr_, "pbrMetallicRoughness"), "baseColorFactor")),
           label() + " has alpha (alphaMode " + mode + ", baseColorFactor alpha " +
               glslFloat(alpha_, FloatDigits::Nine) +
               "): opacity and transmission are not shaded; the engine blends or masks");
    }
  }

  // Enables the feature and binds the library's glTF defaults for it (the glTF spec's
  // convention where the model's default is the seed's), all at the extension's key.
  void enable(const char* extension, const std::string& feature) {
    SourceLocation at = f_.keyAt(ext(extension));
    out_.source.features.push_back({feature, at});
    auto bindings = ctx_.defaults.features.find(feature);
    if (bindings == ctx_.defaults.features.end()) return;
    for (const auto& b : bindings->second) out_.source.bricks.push_back({{b.role, at}, {b.brick, at}});
  }

  // One row of docs/gltf.md's table: model input = glTF factor (constant, glTF default when
  // absent) times an optional texture's texel, `m.<input> = <factor> * p.<texture><swizzle>`.
  struct FactorRule {
    const char* input;
    const char* factor;
    std::vector<double> gltfDefault;
    const char* texture;
    const char* channels;  // of the texel the texture input holds
    bool srgb;
    const char* swizzle;
  };

  void apply(const std::string& object, const FactorRule& r) {
    std::string ptr = at(object, r.factor);
    bool vec = r.gltfDefault.size() == 3;
    std::vector<double> value =
        vec ? numbers(ptr, 3, r.gltfDefault) : std::vector<double>{number(ptr, r.gltfDefault[0])};
    constant(r.input, value, whereOf(ptr), vec ? ptr : "");
    std::string tex = texture(at(object, r.texture), r.texture, r.channels, r.srgb, r.swizzle);
    std::string literal = vec ? vec3Literal(value) : glslFloat(value[0], FloatDigits::Nine);
    if (!tex.empty()) line(std::string("m.") + r.input + " = " + literal + " * " + tex + ";");
  }

  void readClearcoat() {
    // Its bricks (the core specular_brdf as clearcoat_brdf, Schlick at n_c.v, the base left
    // as it is) are the library's glTF defaults (shaderlib/gltf_defaults.json).
    enable(kClearcoat, "clearcoat");
    std::string e = ext(kClearcoat);
    apply(e, {"clearCoat", "clearcoatFactor", {0.0}, "clearcoatTexture", "r", false, ""});
    apply(e, {"clearCoatRoughness", "clearcoatRoughnessFactor", {0.0}, "clearcoatRoughnessTexture", "g", false, ""});
    // The coat's own normal map (a normalTextureInfo): the spec's scaledNormal =
    // normalize((texel * 2 - 1) * (scale, scale, 1)) is the model's tangent-space
    // clearCoatNormal (Filament's), which the model normalizes about the geometric normal.
    std::string normal = texture(at(e, "clearcoatNormalTexture"), "clearcoatNormalTexture", "rgb", false);
    if (!normal.empty()) {
      std::string s = glslFloat(out_.textures.back().scale, FloatDigits::Nine);
      line("m.clearCoatNormal = (" + normal + " * 2.0 - 1.0) * vec3(" + s + ", " + s + ", 1.0);");
    }
  }

  void readSheen() {
    enable(kSheen, "sheen");
    std::string e = ext(kSheen);
    apply(e, {"sheenColor", "sheenColorFactor", {0.0, 0.0, 0.0}, "sheenColorTexture", "rgb", true, ""});
    // Sheen roughness is in the alpha channel (KHR_materials_sheen).
    apply(e, {"sheenRoughness", "sheenRoughnessFactor", {0.0}, "sheenRoughnessTexture", "a", false, ""});
  }

  void readAnisotropy() {
    // KHR_materials_anisotropy's alphas (alpha_t = mix(alpha, 1, s^2)) are the library's glTF
    // default for anisotropy_alpha (shaderlib/gltf_defaults.json).
    enable(kAnisotropy, "anisotropy");
    std::string e = ext(kAnisotropy);
    // Direction in R, G (for the engine's tangent), strength in B (KHR_materials_anisotropy).
    apply(e, {"anisotropy", "anisotropyStrength", {0.0}, "anisotropyTexture", "rgb", false, ".b"});
    std::string rotPtr = at(e, "anisotropyRotation");
    double rotation = number(rotPtr, 0.0);
    out_.anisotropyRotation = rotation;
    if (rotation != 0.0)
      warn("W-GLTF-NOT-SHADED", f_.valueAt(rotPtr),
           label() + " has anisotropyRotation " + glslFloat(rotation, FloatDigits::Nine) +
               " rad: the model takes the anisotropy direction from the frame's tangent, so the "
               "engine must rotate the tangent by it (counter-clockwise about n)");
  }

  // dielectric F0 = min(((ior-1)/(ior+1))^2 * specularColor, 1) * specular
  // (KHR_materials_specular, "Interaction with other extensions"; ior from KHR_materials_ior).
  void readSpecular() {
    std::string iorPtr = at(ext(kIor), "ior");
    double ior = has(kIor) ? number(iorPtr, 1.5) : 1.5;
    if (ior != 0.0 && !(ior >= 1.0)) {
      f_.error("E-PARAM-RANGE", f_.valueAt(iorPtr),
               "'" + JsonFields::describe(iorPtr) + "' is " + glslFloat(ior, FloatDigits::Nine) +
                   ": KHR_materials_ior expects 0 or a value >= 1");
      return;
    }
    double r = ior == 0.0 ? 1.0 : (ior - 1.0) / (ior + 1.0);  // ior 0 stands for f0 = 1
    double f0 = r * r;
    std::string e = ext(kSpecular);
    std::string sPtr = at(e, "specularFactor"), cPtr = at(e, "specularColorFactor");
    double specular = has(kSpecular) ? number(sPtr, 1.0) : 1.0;
    std::vector<double> colour = has(kSpecular) ? numbers(cPtr, 3, {1, 1, 1}) : std::vector<double>{1, 1, 1};
    std::vector<double> scaled, value;
    for (double c : colour) {
      scaled.push_back(f0 * c);
      value.push_back(std::min(f0 * c, 1.0) * specular);
    }
    SourceLocation where = has(kSpecular) ? f_.keyAt(e) : f_.keyAt(ext(kIor));
    constant("f0Dielectric", value, where);

    std::string colourTex, strengthTex;
    if (has(kSpecular)) {
      colourTex = texture(at(e, "specularColorTexture"), "specularColorTexture", "rgb", true);
      strengthTex = texture(at(e, "specularTexture"), "specularTexture", "a", false);
    }
    if (!colourTex.empty() || !strengthTex.empty()) {
      std::string c = vec3Literal(scaled) + (colourTex.empty() ? "" : " * " + colourTex);
      std::string s = glslFloat(specular, FloatDigits::Nine) + (strengthTex.empty() ? "" : " * " + strengthTex);
      line("m.f0Dielectric = min(" + c + ", vec3(1.0)) * (" + s + ");");
    }
    if (specular != 1.0 || !strengthTex.empty())
      warn("W-GLTF-APPROXIMATED", where,
           label() +
               ": specularFactor scales the dielectric F0 only; KHR_materials_specular also "
               "scales F90 and the model keeps it at 1");
  }

  void finishSurface() {
    if (surface_.empty()) return;
    std::string glsl =
        "// Generated from glTF " + label() + ": texture inputs are texels the engine samples (docs/gltf.md).\n";
    glsl += "void surface(inout MaterialInputs m, MaterialParams p) {\n";
    for (const auto& l : surface_) glsl += l + "\n";
    glsl += "}\n";
    out_.source.surface = {glsl, where_};
  }

  JsonFields& f_;
  const FileContext& ctx_;
  std::string ptr_;
  SourceLocation where_;
  GltfMaterial out_;
  std::set<std::string> present_;  // supported extensions this material uses
  double alpha_ = 1.0;
  std::vector<std::string> surface_;
};

}  // namespace

bool isMaterialExtensionSupported(const std::string& name) {
  static const std::set<std::string> kSupported = {kClearcoat, kSheen, kAnisotropy, kSpecular, kIor, kEmissiveStrength};
  return kSupported.count(name) != 0;
}

namespace {

// Extensions that change how a file's meshes or images are stored, never what
// a material computes: the engine decodes them (issue 18: a file requiring Draco or BasisU
// was rejected although materials never read meshes or images).
const std::vector<std::string>& engineExtensions() {
  static const std::vector<std::string> kEngine = {"KHR_draco_mesh_compression", "KHR_mesh_quantization",
                                                   "EXT_meshopt_compression",    "KHR_texture_basisu",
                                                   "EXT_texture_webp",           "EXT_texture_avif"};
  return kEngine;
}

// Understood beyond the material ones: KHR_texture_transform (recorded for the engine) and the
// two the scene import reads (KHR_lights_punctual lights, EXT_lights_image_based: the scene's
// environment is image based).
const std::vector<std::string>& recordedExtensions() {
  static const std::vector<std::string> kRecorded = {kTextureTransform, "KHR_lights_punctual",
                                                     "EXT_lights_image_based"};
  return kRecorded;
}

}  // namespace

bool isExtensionUnderstood(const std::string& name) {
  auto in = [&](const std::vector<std::string>& list) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  return isMaterialExtensionSupported(name) || in(recordedExtensions()) || in(engineExtensions());
}

std::vector<std::string> understoodExtensions() {
  std::vector<std::string> all = {kClearcoat, kSheen, kAnisotropy, kSpecular, kIor, kEmissiveStrength};
  all.insert(all.end(), recordedExtensions().begin(), recordedExtensions().end());
  all.insert(all.end(), engineExtensions().begin(), engineExtensions().end());
  return all;
}

GltfMaterial mapMaterial(JsonFields& f, const FileContext& ctx, size_t index, std::set<std::string>& usedExtensions) {
  return MaterialMapper(f, ctx, index).run(usedExtensions);
}

std::string identifierFrom(const std::string& name) {
  std::string out;
  for (char c : name) {
    bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    // GLSL reserves identifiers containing "__": collapse runs, as for replaced characters.
    char next = keep ? c : '_';
    if (next == '_' && !out.empty() && out.back() == '_') continue;
    out += next;
  }
  if (out.empty() || out == "_") return "";
  if (std::isdigit(static_cast<unsigned char>(out[0])) || out.rfind("gl_", 0) == 0) out = "material_" + out;
  return out;
}

}  // namespace mb::gltf
