// emitFragmentShader (fragment_shader.hpp). The main() written here is what
// docs/fragment-stage.md "Frame, lights and environment" specifies line by line; the CPU
// reference render mirrors it in double, so a change here is a change of that document.
//
// Precision: the interface (attributes, blocks, samplers) is fp32 at every precision, as the
// compute kernel's buffers are. The frame vectors are normalized and the light positions made
// relative to the shaded point in fp32, then converted; the shading runs at the permutation's
// precision. The generated statements are written in fp32 GLSL and rewritten like the
// library at fp16 (fp16_rewrite.hpp), so every interface read is wrapped in a constructor of
// its shading type (`vec3(...)` becomes `f16vec3(...)`), which converts explicitly.
#include "emit/fragment_shader.hpp"

#include <sstream>

#include "emit/fp16_rewrite.hpp"
#include "emit/fragment_textures.hpp"
#include "emit/ltc_table_lookup.hpp"
#include "emit/glsl_writer.hpp"
#include "emit/light_contract.hpp"

namespace mb {
namespace {

// Where MbFrameBlock (shaderlib/common/engine_frame.glsl) keeps one light type's records.
struct LightKind {
  LightType type;
  const char* array;  // MbFrameBlock member
  const char* count;  // its count in MbFrameBlock
};

constexpr LightKind kLightKinds[] = {
    {LightType::Dir, "dirLights", "lightCounts.x"},    {LightType::Point, "pointLights", "lightCounts.y"},
    {LightType::Spot, "spotLights", "lightCounts.z"},  {LightType::Sphere, "sphereLights", "lightCounts.w"},
    {LightType::Tube, "tubeLights", "lightCounts2.x"}, {LightType::Rect, "rectLights", "lightCounts2.y"},
    {LightType::Disk, "diskLights", "lightCounts2.z"},
};

// The contract struct of light `L` (an MbDirectionalLightGpu or MbLocalLightGpu expression)
// relative to the shaded point (engine_frame.glsl's record fields; lights.glsl's structs).
std::string lightStruct(LightType type, const std::string& L) {
  const std::string rel = "vec3(" + L + ".position.xyz - mbWorldPosition)";
  const std::string intensity = "vec3(" + L + ".intensity.rgb), float(" + L + ".intensity.w)";
  if (type == LightType::Dir) return "DirectionalLight(vec3(" + L + ".direction.xyz), vec3(" + L + ".illuminance.rgb))";
  if (type == LightType::Point) return "PointLight(" + rel + ", " + intensity + ")";
  if (type == LightType::Spot)
    return "SpotLight(" + rel + ", vec3(" + L + ".axis.xyz), " + intensity + ", float(" + L + ".axis.w), float(" + L +
           ".params.x))";
  if (type == LightType::Sphere) return "SphereLight(" + rel + ", float(" + L + ".position.w), " + intensity + ")";
  if (isLtcLight(type))
    return lightStructName(type) + "(" + rel + ", vec3(" + L + ".halfX.xyz), vec3(" + L + ".halfY.xyz), vec3(" + L +
           ".luminance.rgb))";
  return "TubeLight(" + rel + ", vec3(" + L + ".axis.xyz - mbWorldPosition), float(" + L + ".position.w), " +
         intensity + ")";
}

class FragmentWriter {
 public:
  FragmentWriter(GlslWriter& w, const ShaderLibrary& lib, const Permutation& perm, ShaderPrecision p)
      : w_(w), lib_(lib), perm_(perm), p_(p), textures_(fragmentTextures(*perm.material)) {
    // Under a mediump default the interface says highp, so the loss of precision happens
    // after the fp32 values are read (as the compute kernel's buffers do).
    hp_ = p == ShaderPrecision::Fp16Mediump ? "highp " : "";
  }

  void write() {
    w_.line("// Fragment stage (docs/fragment-stage.md, interface version " +
            std::to_string(kFragmentInterfaceVersion) + ").");
    declarations();
    hooks();
    main();
  }

 private:
  bool ibl() const { return isIbl(perm_.environment); }
  bool ltc() const { return perm_.readsLtcTable(); }
  // Shading-side text: written in fp32 GLSL, rewritten at fp16.
  void shading(const std::string& glsl) { w_.line(p_ == ShaderPrecision::Fp16 ? rewriteToFp16(glsl) : glsl); }
  const FragmentTexture* textureOf(const std::string& param) const {
    for (const auto& t : textures_)
      if (t.param == param) return &t;
    return nullptr;
  }

  void declarations() {
    if (p_ == ShaderPrecision::Fp16Mediump) w_.line("precision highp float;");
    w_.line("layout(location = 0) in vec3 mbWorldPosition;");
    w_.line("layout(location = 1) in vec3 mbWorldNormal;");
    w_.line("layout(location = 2) in vec4 mbWorldTangent;");
    w_.line("layout(location = 3) in vec2 mbUv0;");
    w_.line("layout(location = 0) out vec4 mbOutColor;");
    // The frame block, byte for byte the same file in every permutation.
    const std::string frame = "common/engine_frame.glsl";
    w_.include(ShaderLibrary::displayPath(frame), lib_.source(frame));
    // The compute kernel's MaterialParamsBlock, member for member (the C++ header's struct
    // fits both); a member a texture feeds is declared but read from its sampler.
    std::vector<std::string> members;
    for (const auto& prm : perm_.material->params)
      if (!prm.constant) members.push_back("    " + std::string(toString(prm.type)) + " " + prm.name + ";");
    if (!members.empty()) {
      w_.line("layout(std140, set = 0, binding = " + std::to_string(kFragmentParamsBinding) +
              ") uniform MbMaterialParams {");
      for (const auto& m : members) w_.line(m);
      w_.line("} mbParams;");
    }
    if (ibl())
      w_.line("layout(set = 0, binding = " + std::to_string(kFragmentPrefilteredBinding) + ") uniform " + hp_ +
              "samplerCube mbPrefilteredEnv;");
    if (usesDfgLut(perm_.environment))
      w_.line("layout(set = 0, binding = " + std::to_string(kFragmentDfgBinding) + ") uniform " + hp_ +
              "sampler2D mbDfgLut;");
    if (ltc())
      w_.line("layout(set = 0, binding = " + std::to_string(kFragmentLtcBinding) + ") uniform " + hp_ +
              "sampler2D mbLtcTable;");
    for (const auto& t : textures_)
      w_.line("layout(set = 0, binding = " + std::to_string(t.binding) + ") uniform " + hp_ + "sampler2D mbTexture" +
              std::to_string(t.binding - kFirstTextureBinding) + ";  // " + t.param + (t.srgb ? ", sRGB view" : ""));
    if (p_ == ShaderPrecision::Fp16Mediump) w_.line("precision mediump float;");
  }

  // The fetch hooks lights.glsl declares, defined as the probe defines them where no texture
  // backs them (probe_scene.cpp): no prefiltered radiance outside the IBL modes, and the DFG
  // texel (0, 1, 0) outside ibl_lut, which the models do not read there.
  void hooks() {
    if (ltc()) ltcHooks();
    if (perm_.environment == EnvironmentMode::None) return;
    const bool half = p_ == ShaderPrecision::Fp16;
    shading("vec3 mb_fetch_prefiltered(vec3 r, float lod) {");
    if (!ibl())
      shading("    return vec3(0.0);");
    else if (half)
      w_.line("    return f16vec3(textureLod(mbPrefilteredEnv, vec3(r), float(lod)).rgb);");
    else
      w_.line("    return textureLod(mbPrefilteredEnv, r, lod).rgb;");
    w_.line("}");
    shading("vec3 mb_fetch_dfg(float NoV, float perceptualRoughness) {");
    if (!usesDfgLut(perm_.environment))
      shading("    return vec3(0.0, 1.0, 0.0);");
    else if (half)
      w_.line("    return f16vec3(textureLod(mbDfgLut, vec2(float(NoV), float(perceptualRoughness)), 0.0).rgb);");
    else
      w_.line("    return textureLod(mbDfgLut, vec2(NoV, perceptualRoughness), 0.0).rgb;");
    w_.line("}");
  }

  // The LTC table (docs/fragment-stage.md "LTC table"), read with texelFetch and blended in
  // fp32 as emit/ltc_table_lookup.cpp explains.
  void ltcHooks() {
    for (const auto& line : ltcTableLookup("texelFetch(mbLtcTable, @, 0)", p_)) w_.line(line);
  }

  void frame() {
    // fp32, interface side.
    const FragmentTexture* normal = textureOf("normalTexture");
    w_.line("    " + hp_ + "vec3 mbNg = normalize(mbWorldNormal);");
    w_.line("    " + hp_ + "vec3 mbT = normalize(mbWorldTangent.xyz);");
    if (normal) {
      // glTF 2.0 spec, "normalTextureInfo": scaledNormal = normalize((texel * 2 - 1) *
      // (scale, scale, 1)) in the tangent frame (t, w cross(n, t), n) of the vertex attributes.
      const std::string s = glslFloat(normal->scale);
      w_.line("    " + hp_ + "vec3 mbB = mbWorldTangent.w * cross(mbNg, mbT);");
      w_.line("    " + hp_ + "vec3 mbTn = (texture(mbTexture" + std::to_string(normal->binding - kFirstTextureBinding) +
              ", mbUv0).rgb * 2.0 - 1.0) * vec3(" + s + ", " + s + ", 1.0);");
      w_.line("    " + hp_ + "vec3 mbN = normalize(mbTn.x * mbT + mbTn.y * mbB + mbTn.z * mbNg);");
    } else {
      w_.line("    " + hp_ + "vec3 mbN = mbNg;");
    }
    w_.line("    " + hp_ + "vec3 mbV = normalize(mbFrame.cameraPosition.xyz - mbWorldPosition);");
    for (const auto& t : textures_) {
      if (t.isNormal()) continue;
      const std::string type = t.channels == "rgb" ? "vec3" : "float";
      w_.line("    " + hp_ + type + " mbTexel" + std::to_string(t.binding - kFirstTextureBinding) +
              " = texture(mbTexture" + std::to_string(t.binding - kFirstTextureBinding) + ", mbUv0)." + t.channels +
              ";");
    }
    // The shading frame at the permutation's precision.
    shading("    ShadingFrame f;");
    shading("    f.n = vec3(mbN);");
    shading("    f.v = vec3(mbV);");
    shading("    f.ng = vec3(mbNg);");
    shading("    f.t = vec3(mbT);");
  }

  std::string materialArgs() const {
    std::string args;
    for (const auto& prm : perm_.material->params) {
      if (prm.constant) continue;
      const FragmentTexture* t = textureOf(prm.name);
      const std::string value =
          t ? "mbTexel" + std::to_string(t->binding - kFirstTextureBinding) : "mbParams." + prm.name;
      args += std::string(args.empty() ? "" : ", ") + toString(prm.type) + "(" + value + ")";
    }
    return args;
  }

  void main() {
    w_.line("void main() {");
    frame();
    shading("    ShadingPixel px = preparePixel(materialInputs(" + materialArgs() + "), f);");
    shading("    vec3 mbRadiance = emittedRadiance(px);");
    for (const auto& k : kLightKinds) {
      if (!perm_.hasLight(k.type)) continue;
      shading(std::string("    for (uint i = 0u; i < min(mbFrame.") + k.count + ", uint(MB_MAX_LIGHTS)); ++i)");
      shading("        mbRadiance += " + lightEntryPoint(k.type) + "(px, f, " +
              lightStruct(k.type, std::string("mbFrame.") + k.array + "[i]") + ");");
    }
    if (perm_.environment != EnvironmentMode::None) {
      shading("    {");
      shading("        Environment env;");
      shading("        for (int k = 0; k < 9; ++k) env.sh[k] = vec3(mbFrame.sh[k].rgb);");
      shading("        env.ao = float(mbFrame.environment.x);");
      shading("        env.maxMip = float(mbFrame.environment.y);");
      shading("        mbRadiance += shadeEnvironment(px, f, env);");
      shading("    }");
    }
    w_.line("    mbOutColor = vec4(vec3(mbRadiance), 1.0);");
    w_.line("}");
  }

  GlslWriter& w_;
  const ShaderLibrary& lib_;
  const Permutation& perm_;
  ShaderPrecision p_;
  std::vector<FragmentTexture> textures_;
  std::string hp_;
};

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

}  // namespace

EmittedShader emitFragmentShader(const ShaderLibrary& lib, const Permutation& perm, bool mediump) {
  return fragmentShaderOf(lib, perm, emitPermutation(lib, perm, false, EmitMode::Engine, mediump), mediump);
}

EmittedShader fragmentShaderOf(const ShaderLibrary& lib, const Permutation& perm, const EmittedShader& kernel,
                               bool mediump) {
  ShaderPrecision p = precisionOf(perm);
  if (mediump && p == ShaderPrecision::Fp16) p = ShaderPrecision::Fp16Mediump;
  EmittedShader out;
  out.key = kernel.key;
  out.bricks = kernel.bricks;
  out.fileName = kernel.fileName.substr(0, kernel.fileName.size() - 5) + ".frag";  // ".glsl"
  GlslWriter w(out.fileName);
  // The kernel's text up to its compute entry point, line for line, so its #line directives
  // stay right; those naming the kernel's own file name the fragment shader instead.
  const std::string kernelFile = "\"" + kernel.fileName + "\"";
  std::istringstream in(kernel.glsl);
  for (std::string line; std::getline(in, line);) {
    if (startsWith(line, "#ifndef MB_NO_PROBE")) break;
    if (startsWith(line, "#line ") && line.size() > kernelFile.size() &&
        line.compare(line.size() - kernelFile.size(), kernelFile.size(), kernelFile) == 0)
      line = line.substr(0, line.size() - kernelFile.size()) + "\"" + out.fileName + "\"";
    w.line(line);
  }
  FragmentWriter(w, lib, perm, p).write();
  out.glsl = w.str();
  return out;
}

}  // namespace mb
