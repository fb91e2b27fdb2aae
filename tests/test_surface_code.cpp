// User surface code (issue 4, "Descriptions" 3): a GLSL snippet computes the model inputs
// from user parameters. The emitted permutation runs it; validation feeds what it computed on
// the GPU to the reference composition; a GLSL error in it is reported at the user's own file
// and line.
#include <catch2/catch.hpp>

#include "compile/glsl_compiler.hpp"
#include "emit/emitter.hpp"
#include "support/harness_support.hpp"
#include "support/pipeline_support.hpp"
#include "validate/validation.hpp"

using namespace mb;

namespace {

// A standard material whose base colour and roughness come from user parameters through
// surface(); `surfaceGlsl` starts at line 12 of "user/tinted.mat".
MaterialDesc tintedMaterial(const std::string& surfaceGlsl) {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m;
  m.name = "tinted";
  m.model = "standard";
  m.sourceFile = "user/tinted.mat";
  m.bricks = {{"roughness", "roughness_clamped"},
              {"diffuse", "diffuse_lambert"},
              {"specular_d", "d_ggx"},
              {"specular_v", "v_smith_ggx_correlated"},
              {"fresnel", "f_schlick"}};
  const ShadingModel* model = lib.findModel("standard");
  for (const auto& in : model->inputs) {
    if (!in.feature.empty()) continue;
    MaterialParam p;
    p.name = in.name;
    p.type = in.type;
    p.value = in.defaultValue;
    p.range = in.range;
    p.constant = true;
    m.params.push_back(p);
  }
  for (const auto& [name, type, lo, hi] : std::vector<std::tuple<std::string, ValueType, double, double>>{
           {"tint", ValueType::Vec3, 0.0, 1.0}, {"wear", ValueType::Float, 0.0, 1.0}}) {
    MaterialParam p;
    p.name = name;
    p.type = type;
    p.value.assign(componentCount(type), 0.5);
    p.range = {lo, hi};
    p.user = true;
    m.params.push_back(p);
  }
  m.surface.glsl = surfaceGlsl;
  m.surface.where = {"user/tinted.mat", 12, 1};
  return m;
}

const char* kSurface =
    "void surface(inout MaterialInputs m, MaterialParams p) {\n"
    "    m.baseColor = p.tint * vec3(0.9, 0.8, 0.7);\n"
    "    m.roughness = mix(0.2, 0.9, p.wear * p.wear);\n"
    "    m.metallic = 1.0 - p.wear;\n"
    "}\n";

}  // namespace

TEST_CASE("surface code runs in the permutation and validates against the fed reference", "[surface][vulkan]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = tintedMaterial(kSurface);
  Permutation perm;
  perm.material = &m;
  ProbeProgram probe = buildPermutationProbe(lib, perm);
  // The probe reads the user parameters and writes back the model inputs surface() computed.
  CHECK(probe.shader.layout.find("tint"));
  CHECK(probe.shader.layout.find("wear"));
  CHECK(probe.shader.layout.fedOutputs.size() == 6);  // baseColor ... ambientOcclusion
  CHECK(probe.shader.glsl.find("#line 12 \"user/tinted.mat\"") != std::string::npos);

  harness::VulkanHarness gpu(harness::testDeviceOptions());
  ValidationRecord r = validateProbe(gpu, probe, "permutation", 2048, 5);
  INFO(r.key << ": max_rel " << r.stats.maxRel << " worst " << r.worstInput);
  CHECK(r.stats.nanCount == 0);
  CHECK(r.passed());

  // The fed values are the user's formulas, evaluated on the GPU: check one of them here.
  ProbeRun run = runProbe(gpu, probe, generateSamples(probe.shader.layout, probe.domain, 64, 9), false);
  const ProbeInput* wear = probe.shader.layout.find("wear");
  const ProbeInput* metallic = nullptr;
  for (const auto& f : probe.shader.layout.fedOutputs)
    if (f.name == "metallic") metallic = &f;
  REQUIRE(metallic);
  for (uint64_t i = 0; i < run.count; ++i) {
    float w = run.inputs[i * probe.shader.layout.inStride + wear->offset];
    CHECK(run.gpu[i * probe.shader.layout.outStride + metallic->offset] == Approx(1.0 - w).margin(1e-6));
  }
}

TEST_CASE("a GLSL error in surface code is reported at the user's file and line", "[surface]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  MaterialDesc m = tintedMaterial(
      "void surface(inout MaterialInputs m, MaterialParams p) {\n"
      "    m.baseColor = p.tint;\n"
      "    m.roughness = p.wearr;\n"
      "}\n");
  Permutation perm;
  perm.material = &m;
  EmittedShader s = emitPermutation(lib, perm);
  try {
    compileComputeGlsl(s.glsl, s.fileName);
    FAIL("the misspelt member compiled");
  } catch (const DiagnosticError& e) {
    REQUIRE(!e.diagnostics().empty());
    const Diagnostic& d = e.diagnostics().front();
    INFO(formatDiagnostic(d));
    CHECK(d.code == "E-GLSL");
    CHECK(d.where.file == "user/tinted.mat");
    CHECK(d.where.line == 14);    // the snippet's third line
    CHECK(d.where.column == 21);  // where 'wearr' starts on that line
  }
}
