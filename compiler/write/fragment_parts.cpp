// write: the fragment stage's part of the package (docs/fragment-stage.md, docs/package.md
// "Fragment shaders"): file paths, the manifest's per-permutation `fragment` object and
// top-level interface, and the C++ header's MbFrameBlock with its binding constants.
#include <algorithm>
#include <sstream>

#include "core/target.hpp"
#include "core/descriptor_bindings.hpp"
#include "core/diagnostics.hpp"
#include "emit/fragment_shader.hpp"
#include "emit/fragment_textures.hpp"
#include "write/package_parts.hpp"

namespace mb {
namespace {

// engine_frame.glsl's block as C++ declares it: member name -> declaration. std140 puts every
// member here at a multiple of 16 and the vec4/uvec4 arrays at a stride of 16, so plain float
// and uint32 arrays match it; the static_asserts below check that against the reflection.
const std::vector<std::pair<std::string, std::string>>& frameMembers() {
  static const std::vector<std::pair<std::string, std::string>> m = {
      {"cameraPosition", "float cameraPosition[4];"},
      {"lightCounts", "std::uint32_t lightCounts[4];"},
      {"lightCounts2", "std::uint32_t lightCounts2[4];"},
      {"dirLights", "MbDirectionalLightGpu dirLights[kMaxLightsPerType];"},
      {"pointLights", "MbLocalLightGpu pointLights[kMaxLightsPerType];"},
      {"spotLights", "MbLocalLightGpu spotLights[kMaxLightsPerType];"},
      {"sphereLights", "MbLocalLightGpu sphereLights[kMaxLightsPerType];"},
      {"tubeLights", "MbLocalLightGpu tubeLights[kMaxLightsPerType];"},
      {"sh", "float sh[9][4];"},
      {"environment", "float environment[4];"},
      {"rectLights", "MbAreaLightGpu rectLights[kMaxLightsPerType];"},
      {"diskLights", "MbAreaLightGpu diskLights[kMaxLightsPerType];"},
  };
  return m;
}

const char* kFrameRecords =
    R"(
// shaderlib/common/engine_frame.glsl's records and std140 block (world space).
struct MbDirectionalLightGpu {
  float direction[4];    // xyz: unit, towards the light
  float illuminance[4];  // rgb
};

struct MbLocalLightGpu {
  float position[4];   // xyz: position (sphere centre, tube start); w: radius (sphere, tube)
  float intensity[4];  // rgb: luminous intensity; w: falloff radius
  float axis[4];       // spot: xyz axis, w cos(outer); tube: xyz segment end
  float params[4];     // spot: x cos(inner)
};

struct MbAreaLightGpu {
  float position[4];   // xyz: centre
  float halfX[4];      // xyz: half edge (rect) or semi-axis (disk)
  float halfY[4];      // xyz: the other; emits towards cross(halfX, halfY)
  float luminance[4];  // rgb: luminance
};

)";

// One constant of the C++ header, its comment in the column the block aligns to.
std::string headerConstant(const std::string& name, int value, const std::string& comment = "") {
  constexpr size_t kCommentColumn = 68;
  std::string line = "inline constexpr std::uint32_t " + name + " = " + std::to_string(value) + ";";
  if (!comment.empty()) line += std::string(std::max<size_t>(2, kCommentColumn - line.size()), ' ') + "// " + comment;
  return line + "\n";
}

// The interface's binding numbers come from descriptor_bindings.hpp, the compiler's own, so
// that the engine's header cannot disagree with the shaders.
std::string frameTypes() {
  return "// The fragment stage's interface, version " + std::to_string(kFragmentInterfaceVersion) +
         " (docs/fragment-stage.md), all in descriptor set 0.\n" +
         headerConstant("kFragmentInterfaceVersion", kFragmentInterfaceVersion) +
         headerConstant("kFragmentParamsBinding", kFragmentParamsBinding, "the material's <material>_Params") +
         headerConstant("kFragmentFrameBinding", kFragmentFrameBinding, "MbFrameBlock") +
         headerConstant("kFragmentPrefilteredEnvBinding", kFragmentPrefilteredBinding,
                        "samplerCube, ibl_* environments") +
         headerConstant("kFragmentDfgLutBinding", kFragmentDfgBinding, "sampler2D, ibl_lut") +
         headerConstant("kFragmentLtcTableBinding", kFragmentLtcBinding, "sampler2D, rect and disk lights") +
         headerConstant("kFragmentFirstTextureBinding", kFirstTextureBinding, "sampler2D per texture record") +
         headerConstant("kMaxLightsPerType", 4, "MB_MAX_LIGHTS") + kFrameRecords;
}

}  // namespace

std::string fragmentPath(const std::string& target, const std::string& hash) {
  return "fragment/" + target + "/" + hash + targetInfo(target).fragmentExtension;
}

nlohmann::json fragmentEntryJson(const PackagedPermutation& p) {
  const BuiltPermutation& b = *p.built;
  nlohmann::json textures = nlohmann::json::array();
  for (const auto& t : fragmentTextures(*p.perm->material))
    textures.push_back({{"binding", t.binding}, {"parameter", t.param}, {"channels", t.channels}, {"srgb", t.srgb}});
  const nlohmann::json& reflection = b.artifacts.fragment.reflection;
  return {{"files", p.fragmentFiles},
          {"spirv_hash_xxh64", b.fragmentHash},
          {"spirv_instructions", b.fragmentInstructions},
          {"textures", std::move(textures)},
          {"reflection", reflection.is_null() ? nlohmann::json::object() : reflection}};
}

nlohmann::json fragmentInterfaceJson() {
  auto binding = [](int b) { return nlohmann::json{{"set", 0}, {"binding", b}}; };
  nlohmann::json params = binding(kFragmentParamsBinding), frame = binding(kFragmentFrameBinding);
  params["layout"] = frame["layout"] = "std140";
  params["block"] = "MbMaterialParams";
  frame["block"] = "MbFrameBlock";
  return {{"interface_version", kFragmentInterfaceVersion},
          {"attributes",
           {{{"location", 0}, {"name", "mbWorldPosition"}, {"type", "vec3"}},
            {{"location", 1}, {"name", "mbWorldNormal"}, {"type", "vec3"}},
            {{"location", 2}, {"name", "mbWorldTangent"}, {"type", "vec4"}},
            {{"location", 3}, {"name", "mbUv0"}, {"type", "vec2"}}}},
          {"output", {{"location", 0}, {"name", "mbOutColor"}, {"type", "vec4"}}},
          {"material_params", std::move(params)},
          {"frame", std::move(frame)},
          {"prefiltered_env", binding(kFragmentPrefilteredBinding)},
          {"dfg_lut", binding(kFragmentDfgBinding)},
          {"ltc_table", binding(kFragmentLtcBinding)},
          {"first_texture", binding(kFirstTextureBinding)}};
}

const nlohmann::json* fragmentFrameBlock(const nlohmann::json& reflection) {
  if (!reflection.is_object() || !reflection.contains("uniform_buffers")) return nullptr;
  for (const auto& u : reflection["uniform_buffers"])
    if (u.value("set", -1) == 0 && u.value("binding", -1) == kFragmentFrameBinding) return &u;
  return nullptr;
}

std::string frameBlockHeader(const nlohmann::json* reflected, const std::string& key) {
  std::ostringstream out;
  out << frameTypes();
  if (!reflected) return out.str();
  const nlohmann::json& members = reflected->at("members");
  const auto& expected = frameMembers();
  auto mismatch = [&](const std::string& what) {
    throw DiagnosticError({{Severity::Error,
                            "E-INTERNAL",
                            {key, 0, 0},
                            "the compiled frame block disagrees with engine_frame.glsl: " + what,
                            ""}});
  };
  if (members.size() != expected.size())
    mismatch("it has " + std::to_string(members.size()) + " members, not " + std::to_string(expected.size()));
  out << "// std140 block MbFrameBlock (set 0, binding " << kFragmentFrameBinding
      << "), the same in every permutation's fragment shader.\nstruct alignas(16) MbFrameBlock {\n";
  for (const auto& [name, decl] : expected) out << "  " << decl << "\n";
  out << "};\n";
  for (size_t i = 0; i < expected.size(); ++i) {
    const std::string& name = expected[i].first;
    if (members[i].at("name") != name) mismatch("member " + std::to_string(i) + " is not '" + name + "'");
    out << "static_assert(offsetof(MbFrameBlock, " << name << ") == " << members[i].at("offset").get<uint64_t>()
        << ", \"std140 offset of " << name << " (SPIRV-Cross)\");\n"
        << "static_assert(sizeof(MbFrameBlock::" << name << ") == " << members[i].at("size").get<uint64_t>()
        << ", \"std140 size of " << name << " (SPIRV-Cross)\");\n";
  }
  const uint64_t size = reflected->at("size").get<uint64_t>();
  out << "static_assert(sizeof(MbFrameBlock) == " << (size + 15) / 16 * 16 << ", \"std140 size " << size
      << " rounded to 16 (SPIRV-Cross)\");\n\n";
  return out.str();
}

}  // namespace mb
