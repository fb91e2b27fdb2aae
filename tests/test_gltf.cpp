// glTF 2.0 material import (docs/gltf.md): the shipped scenes in examples/gltf map to the
// expected features, constants, texture inputs and surface code; .glb equals .gltf;
// unsupported extensions warn or fail; names become unique identifiers.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "load/gltf_container.hpp"
#include "support/gltf_support.hpp"
#include "support/pipeline_support.hpp"

using namespace mb;
using Catch::Matchers::Contains;

namespace {

std::string example(const std::string& file) { return (test::sourceDir() / "examples" / "gltf" / file).string(); }

const SourceParam& param(const MaterialSource& s, const std::string& name) {
  for (const auto& p : s.params)
    if (p.name == name) return p;
  FAIL("no parameter '" << name << "' in " << s.name.value);
  throw;  // unreachable
}

bool hasParam(const MaterialSource& s, const std::string& name) {
  for (const auto& p : s.params)
    if (p.name == name) return true;
  return false;
}

std::vector<std::string> featureNames(const MaterialSource& s) {
  std::vector<std::string> out;
  for (const auto& f : s.features) out.push_back(f.value);
  return out;
}

void requireConstant(const MaterialSource& s, const std::string& name, std::vector<double> value) {
  const SourceParam& p = param(s, name);
  INFO(s.name.value << "." << name);
  CHECK(p.constant);
  REQUIRE(p.value.size() == value.size());
  for (size_t i = 0; i < value.size(); ++i) CHECK(p.value[i] == Approx(value[i]).epsilon(1e-12));
}

void requireTextureInput(const MaterialSource& s, const std::string& name, const std::string& type) {
  const SourceParam& p = param(s, name);
  INFO(s.name.value << "." << name);
  CHECK_FALSE(p.constant);
  CHECK(p.type == type);
  REQUIRE(p.range);
  CHECK(p.range->lo == 0.0);
  CHECK(p.range->hi == 1.0);
}

const std::string kRoot = R"({"asset": {"version": "2.0"}, )";

}  // namespace

TEST_CASE("pbrMetallicRoughness with textures: constants, texture inputs, surface code", "[gltf]") {
  std::string file = example("textured_props.gltf");
  std::string text = test::readFile(file);
  std::vector<GltfMaterial> ms = readGltf(file, test::shippedLibrary());
  REQUIRE(ms.size() == 4);

  const MaterialSource& wood = ms[0].source;
  CHECK(wood.name.value == "Wood_001");
  CHECK(wood.form == "gltf");
  CHECK(wood.model.value == "standard");
  CHECK(featureNames(wood).empty());
  std::vector<std::pair<std::string, std::string>> bricks;
  for (const auto& [role, id] : wood.bricks) bricks.emplace_back(role.value, id.value);
  CHECK(bricks == std::vector<std::pair<std::string, std::string>>{{"roughness", "roughness_clamped"},
                                                                   {"diffuse", "diffuse_lambert"},
                                                                   {"specular_d", "d_ggx"},
                                                                   {"specular_v", "v_smith_ggx_correlated"},
                                                                   {"fresnel", "f_schlick"}});
  requireConstant(wood, "baseColor", {0.9, 0.85, 0.8});
  requireConstant(wood, "metallic", {0.0});
  requireConstant(wood, "roughness", {0.9});
  test::requireAt(param(wood, "roughness").valueWhere, test::positionOf(text, "0.9", "roughnessFactor"));
  requireTextureInput(wood, "baseColorTexture", "vec3");
  requireTextureInput(wood, "metallicRoughnessTexture", "vec3");
  requireTextureInput(wood, "occlusionTexture", "float");
  CHECK_FALSE(hasParam(wood, "normalTexture"));  // the engine perturbs the frame's normal
  CHECK(wood.surface.glsl ==
        "// Generated from glTF material 0 'Wood.001': texture inputs are texels the engine samples (docs/gltf.md).\n"
        "void surface(inout MaterialInputs m, MaterialParams p) {\n"
        "  m.baseColor = vec3(0.9, 0.85, 0.8) * p.baseColorTexture;\n"
        "  m.metallic = 0.0 * p.metallicRoughnessTexture.b;\n"
        "  m.roughness = 0.9 * p.metallicRoughnessTexture.g;\n"
        "  m.ambientOcclusion = 1.0 + 0.8 * (p.occlusionTexture - 1.0);\n"
        "}\n");
  test::requireAt(wood.surface.where, test::positionOf(text, "{", "\"materials\""));
  REQUIRE(ms[0].textures.size() == 4);
  const TextureBinding& occlusion = ms[0].textures[2];
  CHECK(occlusion.param == "occlusionTexture");
  CHECK(occlusion.channels == "r");
  CHECK(occlusion.texture == 1);
  CHECK(occlusion.image == 1);
  CHECK(occlusion.uri == "wood_orm.png");
  CHECK(occlusion.scale == 0.8);
  CHECK(ms[0].textures[0].srgb);
  CHECK_FALSE(ms[0].textures[1].srgb);
  CHECK(ms[0].textures[3].param.empty());  // normalTexture
  CHECK(ms[0].textures[3].scale == 0.5);
  CHECK_THAT(wood.description,
             Contains("baseColorTexture (rgb of the texel): texture 0, image 0 'wood_albedo.png', sRGB, TEXCOORD_0"));
  CHECK(wood.warnings.empty());

  const MaterialSource& lamp = ms[1].source;
  CHECK(lamp.name.value == "Lamp_Shade");
  requireConstant(lamp, "emissive", {1.0, 0.8, 0.5});
  requireTextureInput(lamp, "emissiveTexture", "vec3");
  CHECK_THAT(lamp.surface.glsl, Contains("  m.emissive = vec3(1.0, 0.8, 0.5) * p.emissiveTexture;\n"));
  REQUIRE(ms[1].textures.size() == 1);
  CHECK(ms[1].textures[0].texCoord == 1);
  CHECK(ms[1].textures[0].transform);
  REQUIRE(lamp.warnings.size() == 1);
  CHECK(lamp.warnings[0].code == "W-GLTF-NOT-SHADED");
  CHECK(lamp.warnings[0].severity == Severity::Warning);
  test::requireAt(lamp.warnings[0], test::positionOf(text, "\"BLEND\""));

  const MaterialSource& steel = ms[2].source;
  CHECK(steel.name.value == "Steel");
  CHECK_FALSE(steel.surface.present());
  CHECK(ms[2].textures.empty());
  requireConstant(steel, "metallic", {1.0});
  CHECK_FALSE(hasParam(steel, "emissive"));  // absent in glTF: the model default (none) stands
  CHECK_FALSE(hasParam(steel, "f0Dielectric"));

  // Unnamed, and only a base colour: glTF's defaults (metallic 1, roughness 1), not the model's.
  const MaterialSource& unnamed = ms[3].source;
  CHECK(unnamed.name.value == "textured_props_material3");
  requireConstant(unnamed, "baseColor", {0.2, 0.3, 0.8});
  requireConstant(unnamed, "metallic", {1.0});
  requireConstant(unnamed, "roughness", {1.0});
}

TEST_CASE("KHR extensions: clear coat, sheen, anisotropy, specular + ior, emissive strength", "[gltf]") {
  std::vector<GltfMaterial> ms = readGltf(example("showroom.gltf"), test::shippedLibrary());
  REQUIRE(ms.size() == 5);
  for (const auto& m : ms) {
    INFO(m.source.name.value);
    CHECK(m.source.warnings.empty());  // KHR_lights_punctual is the scene import's, not a warning
  }

  const MaterialSource& paint = ms[0].source;
  CHECK(paint.name.value == "Car_Paint");
  CHECK(featureNames(paint) == std::vector<std::string>{"clearcoat"});
  requireConstant(paint, "clearCoat", {1.0});
  requireConstant(paint, "clearCoatRoughness", {0.04});
  requireConstant(paint, "metallic", {0.7});

  const MaterialSource& velvet = ms[1].source;
  CHECK(featureNames(velvet) == std::vector<std::string>{"sheen"});
  requireConstant(velvet, "sheenColor", {0.1, 0.9, 0.1});
  requireConstant(velvet, "sheenRoughness", {0.8});

  const MaterialSource& brushed = ms[2].source;
  CHECK(brushed.name.value == "Brushed_Aluminium");
  CHECK(featureNames(brushed) == std::vector<std::string>{"anisotropy"});
  requireConstant(brushed, "anisotropy", {0.6});
  requireTextureInput(brushed, "anisotropyTexture", "vec3");
  CHECK_THAT(brushed.surface.glsl, Contains("  m.anisotropy = 0.6 * p.anisotropyTexture.b;\n"));

  // KHR_materials_specular with KHR_materials_ior: f0 = min(((ior-1)/(ior+1))^2 * colour, 1) * specular.
  const MaterialSource& ceramic = ms[3].source;
  CHECK(featureNames(ceramic).empty());
  double f0 = std::pow((1.7 - 1.0) / (1.7 + 1.0), 2.0);
  requireConstant(ceramic, "f0Dielectric", {f0 * 1.0, f0 * 0.9, f0 * 0.8});

  const MaterialSource& neon = ms[4].source;
  requireConstant(neon, "emissive", {40.0, 8.0, 24.0});
}

TEST_CASE("the .glb example gives the same materials as its .gltf", "[gltf]") {
  std::string gltfText = test::readFile(example("showroom.gltf"));
  // The committed .glb is exactly what the spec's layout gives for the .gltf (generator:
  // examples/gltf/make_glb.py).
  CHECK(test::readFile(example("showroom.glb")) == packGlb(gltfText));

  std::vector<GltfMaterial> a = readGltf(example("showroom.gltf"), test::shippedLibrary());
  std::vector<GltfMaterial> b = readGltf(example("showroom.glb"), test::shippedLibrary());
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    const MaterialSource &x = a[i].source, &y = b[i].source;
    CHECK(x.name.value == y.name.value);
    CHECK(featureNames(x) == featureNames(y));
    CHECK(x.surface.glsl == y.surface.glsl);
    REQUIRE(x.params.size() == y.params.size());
    for (size_t k = 0; k < x.params.size(); ++k) {
      CHECK(x.params[k].name == y.params[k].name);
      CHECK(x.params[k].value == y.params[k].value);
      CHECK(x.params[k].constant == y.params[k].constant);
      // Positions in a .glb are those of its JSON chunk, which holds the .gltf text verbatim.
      CHECK(x.params[k].valueWhere.line == y.params[k].valueWhere.line);
      CHECK(x.params[k].valueWhere.column == y.params[k].valueWhere.column);
    }
    CHECK(y.file == example("showroom.glb"));
  }
  // A BIN chunk and chunks of unknown type are skipped.
  std::string withBin = packGlb(gltfText, std::string(10, '\x7f'));
  CHECK(parseGltf(withBin, "x.glb", test::shippedLibrary()).size() == a.size());
}

TEST_CASE("unsupported extensions: a warning when used, an error when required", "[gltf]") {
  std::string file = example("unsupported_used.gltf");
  std::string text = test::readFile(file);
  std::vector<MaterialSource> ms = readGltfMaterials(file, test::shippedLibrary());
  REQUIRE(ms.size() == 1);
  REQUIRE(ms[0].warnings.size() == 2);
  // The file-level one (listed, used by no material) first, then the material's own use.
  const Diagnostic& listed = ms[0].warnings[0];
  CHECK(listed.code == "W-GLTF-UNSUPPORTED-EXTENSION");
  CHECK(listed.severity == Severity::Warning);
  CHECK_THAT(listed.message, Contains("'EXT_mesh_gpu_instancing'"));
  test::requireAt(listed, test::positionOf(text, "\"EXT_mesh_gpu_instancing\""));
  const Diagnostic& used = ms[0].warnings[1];
  CHECK(used.code == "W-GLTF-UNSUPPORTED-EXTENSION");
  CHECK_THAT(used.message, Contains("'KHR_materials_transmission'"));
  CHECK_THAT(used.message, Contains("'Window Glass'"));
  test::requireAt(used, test::positionOf(text, "\"KHR_materials_transmission\"", "\"extensions\""));

  std::string required = example("unsupported_required.gltf");
  std::vector<Diagnostic> ds;
  try {
    readGltf(required, test::shippedLibrary());
    FAIL("an unsupported required extension must fail");
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  Diagnostic d = test::theOne(ds, "E-GLTF-REQUIRED-EXTENSION");
  CHECK(d.where.file == required);
  CHECK_THAT(d.message, Contains("'KHR_materials_transmission'"));
  test::requireAt(d,
                  test::positionOf(test::readFile(required), "\"KHR_materials_transmission\"", "extensionsRequired"));
  CHECK(ds.size() == 1);  // no second (warning) report of the same extension
}

TEST_CASE("material names become unique identifiers", "[gltf]") {
  std::string text = kRoot + R"("materials": [
    {"name": "Material.001"}, {"name": "Material.001"}, {"name": "Material_001"}, {},
    {"name": "1st coat"}, {"name": "gl_Paint"}, {"name": "Mat\u00e9riau  blau"}, {"name": "..."}]})";
  std::vector<MaterialSource> ms;
  for (auto& m : parseGltf(text, "dir/My Scene.gltf", test::shippedLibrary())) ms.push_back(m.source);
  std::vector<std::string> names;
  for (const auto& m : ms) names.push_back(m.name.value);
  CHECK(names == std::vector<std::string>{"Material_001", "Material_001_2", "Material_001_3", "My_Scene_material3",
                                          "material_1st_coat", "material_gl_Paint", "Mat_riau_blau",
                                          "My_Scene_material7"});
}

TEST_CASE("texture-dependent warnings and combinations", "[gltf]") {
  std::string text = kRoot + R"("textures": [{"source": 0}], "images": [{"bufferView": 3}],
  "materials": [{
    "extensions": {
      "KHR_materials_clearcoat": {"clearcoatFactor": 0.5, "clearcoatTexture": {"index": 0},
                                  "clearcoatNormalTexture": {"index": 0, "scale": 0.5}},
      "KHR_materials_anisotropy": {"anisotropyStrength": 0.3, "anisotropyRotation": 0.5},
      "KHR_materials_specular": {"specularFactor": 0.5, "specularColorTexture": {"index": 0}},
      "KHR_materials_sheen": {"sheenRoughnessTexture": {"index": 0}}
    }
  }]})";
  std::vector<GltfMaterial> ms = parseGltf(text, "t.gltf", test::shippedLibrary());
  REQUIRE(ms.size() == 1);
  const MaterialSource& s = ms[0].source;
  // The resolver puts features in the model's order; here the set matters.
  std::vector<std::string> features = featureNames(s);
  std::sort(features.begin(), features.end());
  CHECK(features == std::vector<std::string>{"anisotropy", "clearcoat", "sheen"});
  // glTF defaults for what the extensions leave out, not the model's defaults.
  requireConstant(s, "sheenColor", {0.0, 0.0, 0.0});
  requireConstant(s, "sheenRoughness", {0.0});
  requireConstant(s, "clearCoatRoughness", {0.0});
  requireConstant(s, "f0Dielectric", {0.02, 0.02, 0.02});  // 0.04 * 1 * 0.5
  CHECK_THAT(s.surface.glsl, Contains("  m.clearCoat = 0.5 * p.clearcoatTexture;\n"));
  CHECK_THAT(s.surface.glsl, Contains("  m.sheenRoughness = 0.0 * p.sheenRoughnessTexture;\n"));
  CHECK_THAT(s.surface.glsl,
             Contains("  m.f0Dielectric = min(vec3(0.04, 0.04, 0.04) * p.specularColorTexture, vec3(1.0)) * (0.5);\n"));
  // The coat's normal map is the tangent-space clearCoatNormal, decoded with its scale as the
  // glTF spec's scaledNormal (issue 14, item 6); it is no longer ignored with a warning.
  CHECK_THAT(s.surface.glsl,
             Contains("  m.clearCoatNormal = (p.clearcoatNormalTexture * 2.0 - 1.0) * vec3(0.5, 0.5, 1.0);\n"));
  INFO(DiagnosticError(s.warnings).what());
  REQUIRE(s.warnings.size() == 2);
  CHECK_THAT(s.warnings[0].message, Contains("anisotropyRotation 0.5 rad"));
  CHECK(s.warnings[1].code == "W-GLTF-APPROXIMATED");
  CHECK(ms[0].textures[0].uri == "bufferView 3");
}

TEST_CASE("glTF import resolves every material against the shipped library", "[gltf]") {
  std::vector<MaterialDesc> ds = importGltfMaterials(example("showroom.gltf"), test::shippedLibrary());
  REQUIRE(ds.size() == 5);
  CHECK(ds[0].name == "Car_Paint");
  CHECK(ds[0].form == "gltf");
  CHECK(ds[0].features == std::vector<std::string>{"clearcoat"});
  CHECK(ds[0].bricks.at("specular_v") == "v_smith_ggx_correlated");
  // glTF's coat BRDF is the core specular (KHR_materials_clearcoat), not the seed's Kelemen V.
  CHECK(ds[0].bricks.at("clearcoat_v") == "v_smith_ggx_correlated");
  CHECK(ds[0].bricks.at("f0_clearcoat") == "f0_clearcoat_none");
  CHECK(ds[1].features == std::vector<std::string>{"sheen"});
  CHECK(ds[2].features == std::vector<std::string>{"anisotropy"});
  REQUIRE(ds[2].param("anisotropyTexture"));
  CHECK(ds[2].param("anisotropyTexture")->user);
  CHECK(ds[2].surface.present());
  REQUIRE(ds[4].param("emissive"));
  CHECK(ds[4].param("emissive")->value == std::vector<double>{40.0, 8.0, 24.0});
  // Inputs the glTF leaves out are constants at the model's defaults.
  REQUIRE(ds[4].param("ambientOcclusion"));
  CHECK(ds[4].param("ambientOcclusion")->constant);

  std::vector<MaterialDesc> props = importGltfMaterials(example("textured_props.gltf"), test::shippedLibrary());
  REQUIRE(props.size() == 4);
  CHECK(props[1].warnings.size() == 1);  // alpha, carried from the MaterialSource

  std::vector<MaterialDesc> glass = importGltfMaterials(example("unsupported_used.gltf"), test::shippedLibrary());
  REQUIRE(glass.size() == 1);
  CHECK(glass[0].warnings.size() == 2);
}

TEST_CASE("glTF values outside the model's ranges are located in the glTF", "[gltf]") {
  std::string text = kRoot + R"("materials": [
    {"name": "hot", "emissiveFactor": [1, 1, 1],
     "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 1e31}}},
    {"name": "odd", "pbrMetallicRoughness": {"roughnessFactor": 1.5}}]})";
  test::TempFile file("range.gltf", text);
  std::vector<Diagnostic> ds;
  try {
    importGltfMaterials(file.path(), test::shippedLibrary());
    FAIL("out-of-range values must fail");
  } catch (const DiagnosticError& e) {
    ds = e.diagnostics();
  }
  INFO(DiagnosticError(ds).what());
  // One per emissive component (scaled by the strength, so all three point at it), then roughness.
  REQUIRE(ds.size() == 4);
  for (size_t i = 0; i < 3; ++i) {
    CHECK(ds[i].code == "E-PARAM-RANGE");
    test::requireAt(ds[i], test::positionOf(text, "1e31"));
  }
  CHECK(ds[3].code == "E-PARAM-RANGE");
  test::requireAt(ds[3], test::positionOf(text, "1.5"));

  test::TempFile empty("empty.gltf", kRoot + R"("materials": []})");
  try {
    importGltfMaterials(empty.path(), test::shippedLibrary());
    FAIL("a file without materials must fail");
  } catch (const DiagnosticError& e) {
    test::theOne(e.diagnostics(), "E-GLTF-NO-MATERIALS");
  }
}
