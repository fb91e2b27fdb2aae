// Targets (compile/targets.hpp): SPIRV-Cross outputs and their checks, and reflection.
#include <catch2/catch.hpp>

#include <algorithm>

#include "compile/glsl_compiler.hpp"
#include "compile/hlsl_spirv.hpp"
#include "compile/target_checks.hpp"
#include "compile/targets.hpp"
#include "emit/emitter.hpp"
#include "support/build_support.hpp"
#include "support/cli_support.hpp"

namespace fs = std::filesystem;
using namespace mb;

namespace {

std::vector<BuiltPermutation> buildAllTargets(const std::vector<Permutation>& perms) {
  BuildOptions o;
  o.targets = allTargets();
  return buildPermutations(test::shippedLibrary(), perms, o);
}

const nlohmann::json* findBlock(const nlohmann::json& list, const std::string& name) {
  for (const auto& b : list)
    if (b["name"] == name) return &b;
  return nullptr;
}

}  // namespace

TEST_CASE("fp32 permutations cross-compile to every target and pass its check", "[targets]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  // Standard model with every feature the examples use, and the cloth model.
  const auto& standard = test::loadedMaterials(lib, {"worn_car_paint", "clearcoat_metal", "brushed_metal"});
  const auto& cloth = test::loadedMaterials(lib, {"velvet_green"});
  auto perms = test::permutationsOf(standard, {"dir", "point", "spot", "sphere", "tube"}, EnvironmentMode::IblLut);
  for (const auto& p : test::permutationsOf(cloth, {"dir", "point", "spot"}, EnvironmentMode::Sh)) perms.push_back(p);
  auto built = buildAllTargets(perms);
  REQUIRE(built.size() == perms.size());
  for (const auto& b : built) {
    INFO(b.shader.key);
    REQUIRE(b.artifacts.targets.size() == 4);
    CHECK(b.artifacts.targets.at("glsl450").rfind("#version 450\n", 0) == 0);
    CHECK(b.artifacts.targets.at("essl310").rfind("#version 310 es\n", 0) == 0);
    CHECK(b.artifacts.targets.at("hlsl").find("[numthreads(64, 1, 1)]") != std::string::npos);
    CHECK(b.artifacts.targets.at("msl").find("kernel void main0(") != std::string::npos);
    // OpenGL has no push constants: the block became a uniform block at the first binding no
    // uniform block uses.
    unsigned binding = 0;
    for (const auto& u : b.artifacts.reflection["uniform_buffers"])
      binding = std::max(binding, u["binding"].get<unsigned>() + 1);
    const std::string push = "layout(binding = " + std::to_string(binding) + ", std140) uniform MbPush";
    CHECK(b.artifacts.targets.at("glsl450").find(push) != std::string::npos);
    CHECK(b.artifacts.targets.at("essl310").find(push) != std::string::npos);
  }
}

TEST_CASE("fp16: GLSL 450, HLSL (min16float) and MSL from the half module, ESSL 3.10 from the mediump form",
          "[targets][fp16]") {
  const ShaderLibrary& lib = test::shippedLibrary();
  auto perms = test::permutationsOf(test::loadedMaterials(lib, {"filament_plastic", "clearcoat_metal"}),
                                    {"dir", "point"}, EnvironmentMode::IblLut, Precision::Fp16);
  BuildOptions o;
  o.targets = allTargets();
  auto built = buildPermutations(lib, perms, o);
  REQUIRE(built.size() == 2);
  for (const auto& b : built) {
    INFO(b.shader.key);
    const auto& t = b.artifacts.targets;
    CHECK(t.at("glsl450").find("GL_AMD_gpu_shader_half_float") != std::string::npos);
    CHECK(t.at("hlsl").find("min16float") != std::string::npos);
    CHECK(t.at("msl").find("half") != std::string::npos);
    // ESSL: no 16-bit type, the arithmetic mediump, the record buffers full precision.
    const std::string& es = t.at("essl310");
    CHECK(es.rfind("#version 310 es\n", 0) == 0);
    CHECK(es.find("float16") == std::string::npos);
    CHECK(es.find("GL_AMD") == std::string::npos);
    CHECK(es.find("mediump vec3") != std::string::npos);
    CHECK(es.find("    float mbIn[];") != std::string::npos);
    CHECK(es.find("mediump float mbIn") == std::string::npos);
    // The half module itself cannot go to ESSL: crossCompile says why.
    try {
      crossCompile(b.artifacts.spirv, Target::Essl310, b.shader.fileName);
      FAIL("essl310 of a Float16 module was built");
    } catch (const DiagnosticError& e) {
      REQUIRE(e.diagnostics().size() == 1);
      CHECK(e.diagnostics()[0].code == "E-TARGET-FAILED");
      CHECK(e.diagnostics()[0].message.find("no 16-bit float type") != std::string::npos);
    }
  }
  // The mediump form: MB_FP16's guards and the fp16 roughness floor, fp32 types, RelaxedPrecision.
  EmittedShader mediump = emitPermutation(lib, perms[0], false, EmitMode::Engine, true);
  CHECK(mediump.fileName == perms[0].key() + ".mediump.glsl");
  CHECK(mediump.glsl.find("precision mediump float;") != std::string::npos);
  CHECK(mediump.glsl.find("#define MB_FP16 1") != std::string::npos);
  CHECK(mediump.glsl.find("float16_t") == std::string::npos);
  CHECK(std::find(mediump.bricks.begin(), mediump.bricks.end(), "roughness_clamped_fp16") != mediump.bricks.end());
  auto relaxedCount = [](const std::vector<uint32_t>& spirv) {
    constexpr uint32_t kOpDecorate = 71, kRelaxedPrecision = 0;
    size_t n = 0;
    for (size_t i = 5; i < spirv.size() && (spirv[i] >> 16); i += spirv[i] >> 16)
      n += (spirv[i] & 0xffff) == kOpDecorate && (spirv[i] >> 16) == 3 && spirv[i + 2] == kRelaxedPrecision;
    return n;
  };
  CHECK(relaxedCount(compileComputeGlsl(mediump.glsl, mediump.fileName).spirv) > 100);
  auto fp32 =
      test::permutationsOf(test::loadedMaterials(lib, {"filament_plastic"}), {"dir", "point"}, EnvironmentMode::IblLut);
  CHECK(relaxedCount(
            compileComputeGlsl(emitPermutation(lib, fp32[0], false, EmitMode::Engine, true).glsl, "fp32").spirv) == 0);
}

TEST_CASE("each target's check rejects a broken output", "[targets]") {
  const std::string ok =
      "#version 450\nlayout(local_size_x = 1) in;\nlayout(binding = 0, std430) buffer B { float x[]; } b;\n"
      "void main() { b.x[gl_GlobalInvocationID.x] = 1.0; }\n";
  CHECK(checkGlsl(ok, false).empty());
  CHECK(checkGlsl(ok, true).find("#version 310 es") != std::string::npos);  // not the ES target's
  std::string es = ok;
  es.replace(0, 12, "#version 310 es");
  CHECK(checkGlsl(es, true).empty());
  // A plain uniform needs a location in GL SPIR-V: the check sees what a driver would reject.
  CHECK(!checkGlsl("#version 450\nlayout(local_size_x = 1) in;\nuniform float u;\nvoid main() {}\n", false).empty());
  CHECK(!checkGlsl("#version 450\nvoid main() { undefined(); }\n", false).empty());

  const std::string hlsl =
      "RWByteAddressBuffer o : register(u0);\n[numthreads(64, 1, 1)]\n"
      "void main(uint3 id : SV_DispatchThreadID) { o.Store(id.x * 4, asuint(1.0f)); }\n";
  CHECK(checkHlsl(hlsl).empty());
  CHECK(checkHlsl("[numthreads(64, 1, 1)]\nvoid notMain() {}\n").find("no entry point 'main'") != std::string::npos);
  CHECK(!checkHlsl("[numthreads(64, 1, 1)]\nvoid main() { float3 x = undefined; }\n").empty());

  // MSL: a real module's MSL passes; without its kernel or with a wrong buffer index it fails.
  auto spirv = compileComputeGlsl(ok, "ok.comp").spirv;
  std::string msl = crossCompile(spirv, Target::Msl, "ok.comp");
  SpvcModule m(spirv, SPVC_BACKEND_MSL);
  REQUIRE(m.ok());
  // The indices are assigned while compiling: compile this module too before checking.
  const char* out = nullptr;
  REQUIRE(spvc_compiler_compile(m.compiler(), &out) == SPVC_SUCCESS);
  CHECK(checkMsl(msl, m).empty());
  std::string noKernel = msl;
  noKernel.replace(noKernel.find("kernel void main0("), 6, "static");
  CHECK(checkMsl(noKernel, m).find("kernel") != std::string::npos);
  std::string wrongIndex = msl;
  wrongIndex.replace(wrongIndex.find("[[buffer(0)]]"), 13, "[[buffer(7)]]");
  CHECK(checkMsl(wrongIndex, m).find("[[buffer(0)]]") != std::string::npos);
}

TEST_CASE("MSL: a block the entry point never reads needs no argument", "[targets]") {
  // Unoptimized modules (fp16 units, -O0) keep a parameter block whose members are all fed
  // by textures instead; SPIRV-Cross's MSL declares only the resources main0 uses.
  const std::string glsl = R"(#version 450
layout(local_size_x = 64) in;
layout(std140, set = 0, binding = 2) uniform Params { vec3 unused; } params;
layout(std430, set = 0, binding = 1) writeonly buffer Out { float result[]; } outBuf;
void main() { outBuf.result[gl_GlobalInvocationID.x] = 1.0; }
)";
  CompileOptions co;
  co.optimization = OptimizationLevel::O0;
  const auto spirv = compileComputeGlsl(glsl, "unused_block.comp", co).spirv;
  REQUIRE(reflectSpirv(spirv)["uniform_buffers"].size() == 1);  // still in the module
  const std::string msl = crossCompile(spirv, Target::Msl, "unused_block.comp");
  CHECK(msl.find("& params [[") == std::string::npos);             // no argument for the block
  CHECK(msl.find("& outBuf [[buffer(0)]]") != std::string::npos);  // the buffer that is used
}

TEST_CASE("textured glTF materials at fp16 cross-compile to MSL", "[targets][fp16][cli]") {
  const fs::path dir = test::freshTempDir("targets", "msl_fp16");
  auto r = test::runCli("compile -q --no-cache " + (test::sourceDir() / "examples/gltf/textured_props.gltf").string() +
                        " --precision fp16 --targets spirv,msl -o " + (dir / "pkg").string());
  INFO(r.output);
  CHECK(r.exitCode == 0);
  CHECK(r.output.find("E-TARGET-FAILED") == std::string::npos);
}

TEST_CASE("reflection gives exact std140 offsets of a uniform block, and the buffers of a permutation",
          "[targets][reflection]") {
  const std::string glsl = R"(#version 450
layout(local_size_x = 32, local_size_y = 2) in;
layout(std140, set = 0, binding = 2) uniform Params { vec3 tint; float wear; vec2 uv; float rough[2]; mat3 m; } params;
layout(std430, set = 0, binding = 0) readonly buffer In { float data[]; } inBuf;
layout(std430, set = 0, binding = 1) writeonly buffer Out { float result[]; } outBuf;
layout(push_constant) uniform Push { uint count; float scale; } pc;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  outBuf.result[i] = inBuf.data[i] * pc.scale * params.tint.x * params.wear * params.uv.y * params.rough[1] * params.m[2].z;
}
)";
  nlohmann::json r = reflectSpirv(compileComputeGlsl(glsl, "params.comp").spirv);
  INFO(r.dump(2));
  CHECK(r["entry_point"] == "main");
  CHECK(r["workgroup_size"] == nlohmann::json({32, 2, 1}));
  REQUIRE(r["uniform_buffers"].size() == 1);
  const auto& u = r["uniform_buffers"][0];
  CHECK(u["name"] == "Params");
  CHECK(u["set"] == 0);
  CHECK(u["binding"] == 2);
  // std140: vec3 at 0 (16-aligned), the float packs into its 4th component at 12, vec2 at 16,
  // float[2] with a 16-byte stride at 32, mat3 as three 16-byte columns at 64; 112 in all.
  const nlohmann::json expected = nlohmann::json::parse(R"([
    {"name":"tint","type":"vec3","offset":0,"size":12},
    {"name":"wear","type":"float","offset":12,"size":4},
    {"name":"uv","type":"vec2","offset":16,"size":8},
    {"name":"rough","type":"float[2]","offset":32,"size":32},
    {"name":"m","type":"mat3","offset":64,"size":48}])");
  CHECK(u["members"] == expected);
  CHECK(u["size"] == 112);
  REQUIRE(r["storage_buffers"].size() == 2);
  const auto* in = findBlock(r["storage_buffers"], "In");
  const auto* out = findBlock(r["storage_buffers"], "Out");
  REQUIRE(in);
  REQUIRE(out);
  CHECK((*in)["binding"] == 0);
  CHECK((*in)["readonly"] == true);
  CHECK((*in)["writeonly"] == false);
  CHECK((*out)["binding"] == 1);
  CHECK((*out)["writeonly"] == true);
  CHECK((*in)["members"][0]["type"] == "float[]");
  REQUIRE(r["push_constants"].size() == 1);
  CHECK(r["push_constants"][0]["name"] == "Push");
  CHECK(r["push_constants"][0]["size"] == 8);
  CHECK(r["push_constants"][0]["members"][1] ==
        nlohmann::json({{"name", "scale"}, {"type", "float"}, {"offset", 4}, {"size", 4}}));
  CHECK(!r["push_constants"][0].contains("binding"));

  // A permutation's kernel (docs/package.md "Kernel ABI"): records in, results out, a count.
  auto perms = test::permutationsOf(test::loadedMaterials(test::shippedLibrary(), {"ue4_metal"}), {"dir"},
                                    EnvironmentMode::None);
  auto built = buildPermutations(test::shippedLibrary(), perms, {});
  const auto& pr = built[0].artifacts.reflection;
  INFO(pr.dump(2));
  CHECK(pr["workgroup_size"][0] == 64);
  const auto* mbIn = findBlock(pr["storage_buffers"], "MbIn");
  const auto* mbOut = findBlock(pr["storage_buffers"], "MbOut");
  REQUIRE(mbIn);
  REQUIRE(mbOut);
  CHECK((*mbIn)["readonly"] == true);
  CHECK((*mbOut)["writeonly"] == true);
  REQUIRE(pr["push_constants"].size() == 1);
  CHECK(pr["push_constants"][0]["members"][0] ==
        nlohmann::json({{"name", "count"}, {"type", "uint"}, {"offset", 0}, {"size", 4}}));
}

TEST_CASE("crossCompile names the permutation and the target when SPIRV-Cross cannot read the module", "[targets]") {
  std::vector<uint32_t> garbage{0x07230203, 0x00010000, 0, 5, 0, 0xdeadbeef};
  try {
    crossCompile(garbage, Target::Hlsl, "broken.glsl");
    FAIL("garbage cross-compiled");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics()[0].code == "E-TARGET-FAILED");
    CHECK(e.diagnostics()[0].where.file == "broken.glsl");
    CHECK(e.diagnostics()[0].message.find("target hlsl: SPIRV-Cross") != std::string::npos);
  }
  CHECK(spirvCrossVersion().find("SPIRV-Cross") != std::string::npos);
  for (const auto& t : allTargets()) CHECK(!targetOptions(t).empty());
}

TEST_CASE("the webgl2 check: ESSL 3.00 as glslang reads it, and WebGL 2.0's own identifier rules", "[targets]") {
  const std::string frag =
      "#version 300 es\nprecision highp float;\nuniform Blk { vec4 c; } blk;\nout vec4 o;\n"
      "void main() { o = blk.c; }\n";
  CHECK(checkWebgl2(frag, ShaderStage::Fragment).empty());
  CHECK(checkWebgl2("#version 300 es\nlayout(location = 0) in vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n",
                    ShaderStage::Vertex)
            .empty());
  // What ES 3.00 lacks: binding qualifiers (ES 3.10), storage buffers, compute.
  std::string bound = frag;
  bound.replace(bound.find("uniform Blk"), 11, "layout(binding = 1) uniform Blk");
  CHECK(checkWebgl2(bound, ShaderStage::Fragment).find("glslang") != std::string::npos);
  CHECK(!checkWebgl2("#version 300 es\nbuffer B { float x[]; };\nvoid main() {}\n", ShaderStage::Fragment).empty());
  CHECK(checkWebgl2(frag, ShaderStage::Compute).find("no compute") != std::string::npos);
  CHECK(checkWebgl2("#version 310 es\n" + frag.substr(16), ShaderStage::Fragment).find("#version 300 es") !=
        std::string::npos);
  // WebGL 2.0 section 5: reserved prefixes; identifiers of at most 1024 characters.
  std::string reserved = frag;
  reserved.replace(reserved.find("blk;"), 3, "webgl_blk");
  reserved.replace(reserved.find("blk.c"), 3, "webgl_blk");
  CHECK(checkWebgl2(reserved, ShaderStage::Fragment).find("webgl_") != std::string::npos);
  std::string longName = frag;
  const std::string name(1025, 'a');
  longName.replace(longName.find("blk;"), 3, name);
  longName.replace(longName.find("blk.c"), 3, name);
  CHECK(checkWebgl2(longName, ShaderStage::Fragment).find("name too long") != std::string::npos);  // glslang's

  // A compute module is refused by name; a fragment module cross-compiles without bindings.
  const std::string kernel =
      "#version 450\nlayout(local_size_x = 1) in;\nlayout(binding = 0, std430) buffer B { "
      "float x[]; } b;\nvoid main() { b.x[0] = 1.0; }\n";
  try {
    crossCompile(compileComputeGlsl(kernel, "k.comp").spirv, Target::Webgl2, "k.comp");
    FAIL("a compute shader cross-compiled to webgl2");
  } catch (const DiagnosticError& e) {
    CHECK(e.diagnostics().at(0).code == "E-TARGET-FAILED");
  }
  CompileOptions fragment;
  fragment.stage = ShaderStage::Fragment;
  const std::string vulkan =
      "#version 450\nlayout(binding = 3) uniform sampler2D tex;\nlayout(binding = 1) uniform "
      "Blk { vec4 c; } blk;\nlayout(location = 0) in vec2 uv;\nlayout(location = 0) out vec4 "
      "o;\nvoid main() { o = blk.c * texture(tex, uv); }\n";
  const std::string webgl =
      crossCompile(compileComputeGlsl(vulkan, "f.frag", fragment).spirv, Target::Webgl2, "f.frag");
  CHECK(webgl.rfind("#version 300 es\n", 0) == 0);
  CHECK(webgl.find("binding") == std::string::npos);
  CHECK(webgl.find("uniform Blk") != std::string::npos);
  CHECK(webgl.find("sampler2D tex;") != std::string::npos);
}

TEST_CASE("HLSL for Vulkan: inputs at their TEXCOORD locations, samplers shifted off their textures' bindings",
          "[targets]") {
  const std::string hlsl =
      "Texture2D<float4> tex : register(t2, space0);\nSamplerState _tex_sampler : register(s2, space0);\n"
      "struct SPIRV_Cross_Input\n{\n    float3 a : TEXCOORD0;\n    float2 uv : TEXCOORD3;\n};\n"
      "struct SPIRV_Cross_Output\n{\n    float4 o : SV_Target0;\n};\n"
      "SPIRV_Cross_Output main(SPIRV_Cross_Input i)\n{\n    SPIRV_Cross_Output r;\n"
      "    r.o = tex.Sample(_tex_sampler, i.uv) + float4(i.a, 0.0);\n    return r;\n}\n";
  const std::string located = hlslWithInputLocations(hlsl);
  CHECK(located.find("[[vk::location(0)]] float3 a : TEXCOORD0;") != std::string::npos);
  CHECK(located.find("[[vk::location(3)]] float2 uv : TEXCOORD3;") != std::string::npos);
  CHECK(located.find("[[vk::location(0)]] float4 o") == std::string::npos);  // outputs are left alone
  // The decorations glslang gives, as words of the module: OpDecorate id Location n / Binding n.
  auto decorations = [](const std::vector<uint32_t>& spirv, uint32_t decoration) {
    std::vector<uint32_t> values;
    for (size_t i = 5; i < spirv.size() && (spirv[i] >> 16); i += spirv[i] >> 16)
      if ((spirv[i] & 0xffff) == 71 && (spirv[i] >> 16) == 4 && spirv[i + 2] == decoration)
        values.push_back(spirv[i + 3]);
    std::sort(values.begin(), values.end());
    return values;
  };
  constexpr uint32_t kLocation = 30, kBinding = 33;
  std::vector<uint32_t> plain, shifted;
  REQUIRE(compileHlsl(hlsl, plain, true) == "");
  REQUIRE(compileHlsl(located, shifted, true, kHlslSamplerShift) == "");
  CHECK(decorations(plain, kLocation) == std::vector<uint32_t>{0, 0, 1});  // declaration order: uv at 1
  CHECK(decorations(shifted, kLocation) == std::vector<uint32_t>{0, 0, 3});
  CHECK(decorations(plain, kBinding) == std::vector<uint32_t>{2, 2});  // both at 2: not a valid Vulkan layout
  CHECK(decorations(shifted, kBinding) == std::vector<uint32_t>{2, 2 + kHlslSamplerShift});
}
