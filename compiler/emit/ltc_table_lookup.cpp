#include "emit/ltc_table_lookup.hpp"

#include "core/descriptor_bindings.hpp"
#include "emit/fp16_rewrite.hpp"

namespace mb {
namespace {

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

// Under a mediump default the lookup says highp: the table's values are fp32 and the blend
// is fp32 arithmetic, as the kernel's buffers are read at fp32.
std::string highpAt(ShaderPrecision p) { return p == ShaderPrecision::Fp16Mediump ? "highp " : ""; }

}  // namespace

// The tables (shaderlib/ltc/ggx.json, then charlie.json) as 256 x 64 RGBA entries: the
// specular table's M^-1 in columns 0-63 and its magnitudes in 64-127 (rg), the sheen's in
// 128-191 and 192-255; row i is perceptual roughness i / 63, column j is u = j / 63 with
// n.v = 1 - u^2. Interpolated from four entries rather than by a sampler: a
// GPU's bilinear filter may weigh texels with as few as 4 fractional bits (Vulkan's minimum
// subTexelPrecisionBits), and neighbouring entries of M^-1 differ by up to 44 % (m22), near
// grazing views by their whole value (the shipped table, roughness >= 0.05), so the filter's
// rounding would decide the result; in fp32 arithmetic every conforming GPU computes the same.
std::vector<std::string> ltcTableLookup(const std::string& entry, ShaderPrecision p) {
  const std::string hp = highpAt(p);
  const bool half = p == ShaderPrecision::Fp16;
  const std::string last = std::to_string(kLtcTableSize - 1) + ".0",
                    secondLast = std::to_string(kLtcTableSize - 2) + ".0";
  auto at = [&](const std::string& c) { return replaceAll(entry, "@", c); };
  auto shading = [&](const std::string& glsl) { return half ? rewriteToFp16(glsl) : glsl; };
  const std::string args = half ? "float(NoV), float(perceptualRoughness)" : "NoV, perceptualRoughness";
  auto hooks = [&](const std::string& lobe, int column0) {
    return std::vector<std::string>{
        shading("vec4 mb_fetch_ltc" + lobe + "_matrix(float NoV, float perceptualRoughness) {"),
        std::string("    return ") + (half ? "f16vec4(" : "(") + "mb_ltc_texel(" + args + ", " +
            std::to_string(column0) + "));",
        "}",
        shading("vec2 mb_fetch_ltc" + lobe + "_magnitude(float NoV, float perceptualRoughness) {"),
        std::string("    return ") + (half ? "f16vec2(" : "(") + "mb_ltc_texel(" + args + ", " +
            std::to_string(column0 + kLtcTableSize) + ").xy);",
        "}",
    };
  };
  std::vector<std::string> out{
      hp + "vec4 mb_ltc_texel(" + hp + "float NoV, " + hp + "float perceptualRoughness, int column0) {",
      "    " + hp + "vec2 p = clamp(vec2(sqrt(max(1.0 - NoV, 0.0)), perceptualRoughness), 0.0, 1.0) * " + last + ";",
      "    " + hp + "vec2 i = min(floor(p), vec2(" + secondLast + "));",
      "    " + hp + "vec2 t = p - i;",
      "    ivec2 c = ivec2(i) + ivec2(column0, 0);",
      "    " + hp + "vec4 a = mix(" + at("c") + ", " + at("c + ivec2(1, 0)") + ", t.x);",
      "    " + hp + "vec4 b = mix(" + at("c + ivec2(0, 1)") + ", " + at("c + ivec2(1, 1)") + ", t.x);",
      "    return mix(a, b, t.y);",
      "}",
  };
  for (const auto& line : hooks("", 0)) out.push_back(line);
  for (const auto& line : hooks("_sheen", 2 * kLtcTableSize)) out.push_back(line);
  return out;
}

std::vector<std::string> ltcTableBufferHooks(ShaderPrecision p) {
  const std::string hp = highpAt(p);
  std::vector<std::string> out{
      "// The LTC table, the harness's table buffer: entry (column, row) at floats 4 (row * " +
          std::to_string(kLtcTextureWidth) + " + column), RGBA.",
      "layout(std430, set = 0, binding = " + std::to_string(kKernelTableBinding) + ") readonly buffer MbTable { " + hp +
          "float mbTable[]; };",
      hp + "vec4 mb_ltc_table_entry(ivec2 c) {",
      "    uint k = uint(c.y * " + std::to_string(kLtcTextureWidth) + " + c.x) * 4u;",
      "    return vec4(mbTable[k], mbTable[k + 1u], mbTable[k + 2u], mbTable[k + 3u]);",
      "}",
  };
  for (const auto& line : ltcTableLookup("mb_ltc_table_entry(@)", p)) out.push_back(line);
  return out;
}

}  // namespace mb
