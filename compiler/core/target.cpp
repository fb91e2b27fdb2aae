#include "core/target.hpp"

#include <array>
#include <stdexcept>

namespace mb {
namespace {

// The one place a target is described. SPIR-V is what every other target is made from.
constexpr std::array<TargetInfo, 6> kTargets{{
    {Target::Spirv, "spirv", ".spv", ".spv", TargetLanguage::Spirv, false, 0, true, "", ""},
    {Target::Glsl450, "glsl450", ".comp", ".frag", TargetLanguage::Glsl, false, 450, true, " non-vulkan push-as-ubo",
     ""},
    {Target::Essl310, "essl310", ".es.comp", ".es.frag", TargetLanguage::Glsl, true, 310, false,
     " non-vulkan push-as-ubo fp16-as-mediump", ""},
    {Target::Hlsl, "hlsl", ".hlsl", ".hlsl", TargetLanguage::Hlsl, false, 60, true, " min16float", ".hlsl"},
    {Target::Msl, "msl", ".metal", ".metal", TargetLanguage::Msl, false, 20300, true, " macos", ".metal"},
    // WebGL 2.0 runs ESSL 3.00 (WebGL 2.0 spec, "Differences Between WebGL and OpenGL ES 3.0"):
    // no compute, no binding qualifiers; blocks and samplers are bound by name.
    {Target::Webgl2, "webgl2", "", ".webgl2.frag", TargetLanguage::Glsl, true, 300, false,
     " non-vulkan push-as-ubo fp16-as-mediump no-bindings", "", false},
}};

}  // namespace

const TargetInfo& targetInfo(Target t) {
  for (const auto& info : kTargets)
    if (info.target == t) return info;
  throw std::logic_error("targetInfo: a Target without a row in the table");
}

const TargetInfo& targetInfo(std::string_view name) {
  if (auto t = parseTarget(name)) return targetInfo(*t);
  throw std::logic_error("targetInfo: '" + std::string(name) + "' is not a target");
}

const std::string& targetName(Target t) {
  return allTargetNames()[static_cast<size_t>(&targetInfo(t) - kTargets.data())];
}

const std::vector<Target>& allTargets() {
  static const std::vector<Target> v = [] {
    std::vector<Target> out;
    for (const auto& info : kTargets) out.push_back(info.target);
    return out;
  }();
  return v;
}

const std::vector<std::string>& allTargetNames() {
  static const std::vector<std::string> v = [] {
    std::vector<std::string> out;
    for (const auto& info : kTargets) out.push_back(info.name);
    return out;
  }();
  return v;
}

std::optional<Target> parseTarget(std::string_view name) {
  for (const auto& info : kTargets)
    if (name == info.name) return info.target;
  return std::nullopt;
}

std::vector<Target> parseTargets(const std::vector<std::string>& names) {
  std::vector<Target> out;
  for (const auto& n : names) {
    auto t = parseTarget(n);
    if (!t) throw std::invalid_argument("not a target: '" + n + "'");
    out.push_back(*t);
  }
  return out;
}

std::vector<std::string> targetNames(const std::vector<Target>& targets) {
  std::vector<std::string> out;
  for (Target t : targets) out.push_back(targetName(t));
  return out;
}

}  // namespace mb
