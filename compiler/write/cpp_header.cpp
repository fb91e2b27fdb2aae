// write: the package's C++17 header (docs/package.md "C++ header"). The parameter structs are
// declared from the material's parameter types by std140's rules (GLSL 4.50 spec 7.6.2.2:
// float 4-aligned, vec2 8, vec3/vec4 16, struct size rounded to 16), and every offset and the
// size are static_asserted against the SPIRV-Cross reflection of the compiled module, so a
// disagreement between our C++ layout and the SPIR-V is a compile error in the engine.
#include <cctype>
#include <map>
#include <sstream>

#include "core/descriptor_bindings.hpp"
#include "core/diagnostics.hpp"
#include "emit/fragment_textures.hpp"
#include "write/package_parts.hpp"

namespace mb {
namespace {

std::string identifier(const std::string& name) {
  std::string id;
  for (char c : name) id += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "m_" + id;
  return id;
}

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return q + "\"";
}

std::string memberDecl(const std::string& name, ValueType type) {
  switch (type) {
    case ValueType::Float:
      return "float " + name + ";";
    case ValueType::Vec2:
      return "alignas(8) float " + name + "[2];";
    default:
      return "alignas(16) float " + name + "[3];";
  }
}

[[noreturn]] void layoutMismatch(const PackagedPermutation& p, const std::string& what) {
  throw DiagnosticError({{Severity::Error,
                          "E-INTERNAL",
                          {p.built->shader.key, 0, 0},
                          "the compiled parameter block disagrees with the material: " + what,
                          ""}});
}

// One distinct parameter block: its C++ struct text (without the name) and the asserts.
struct Block {
  std::string name;
  std::string members;  // declarations, one per line
  std::string asserts;  // static_asserts, with NAME standing for the struct name
  uint64_t size = 0;    // SPIRV-Cross declared size
};

Block blockOf(const PackagedPermutation& p, const nlohmann::json& reflected) {
  Block b;
  b.size = reflected.at("size").get<uint64_t>();
  const nlohmann::json& members = reflected.at("members");
  size_t k = 0;
  for (const auto& prm : p.perm->material->params) {
    if (prm.constant) continue;
    if (k >= members.size() || members[k].at("name") != prm.name)
      layoutMismatch(p, "member " + std::to_string(k) + " is not '" + prm.name + "'");
    b.members += "  " + memberDecl(prm.name, prm.type) + "\n";
    b.asserts += "static_assert(offsetof(NAME, " + prm.name +
                 ") == " + std::to_string(members[k].at("offset").get<uint64_t>()) + ", \"std140 offset of " +
                 prm.name + " (SPIRV-Cross)\");\n";
    ++k;
  }
  if (k != members.size()) layoutMismatch(p, "the block has " + std::to_string(members.size()) + " members");
  const uint64_t rounded = (b.size + 15) / 16 * 16;
  b.asserts += "static_assert(sizeof(NAME) == " + std::to_string(rounded) + ", \"std140 size " +
               std::to_string(b.size) + " rounded to 16 (SPIRV-Cross)\");\n";
  return b;
}

std::string replaceName(std::string text, const std::string& name) {
  for (size_t at = text.find("NAME"); at != std::string::npos; at = text.find("NAME", at + name.size()))
    text.replace(at, 4, name);
  return text;
}

const char* kPreamble = R"(#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

)";

const char* kTypes =
    R"(// One input of a shading record: `offset` and `components` in floats (docs/package.md "Kernel ABI").
struct RecordInput {
  std::string_view name;
  std::uint32_t offset;
  std::uint32_t components;
};

struct Permutation {
  std::string_view key;
  std::string_view material;
  std::string_view spirv;         // the kernel, relative to the package directory; "" when none
  std::string_view include;       // the GLSL include, relative to the package directory
  std::string_view paramsStruct;  // the parameter struct's name, empty when there is no block
  std::size_t paramsSize;         // bytes of the std140 parameter block (0: none)
  std::uint32_t recordStride;     // floats per shading record (binding 0)
  std::uint32_t resultStride;     // floats per result (binding 1)
  const RecordInput* inputs;
  std::size_t inputCount;
  std::string_view fragmentSpirv;      // the fragment shader (docs/fragment-stage.md), "" when none
  std::uint32_t fragmentTextureCount;  // its textures, at kFragmentFirstTextureBinding + i
};

)";

const char* kLookups = R"(
inline constexpr std::size_t kPermutationCount = sizeof(kPermutations) / sizeof(kPermutations[0]);

// The permutation of `key`, or nullptr: static_assert(findPermutation("...")) makes a missing
// permutation a build error, never a fallback.
constexpr const Permutation* findPermutation(std::string_view key) {
  for (const Permutation& p : kPermutations)
    if (p.key == key) return &p;
  return nullptr;
}

// The same as a bool, for static_assert(hasPermutation("...")).
constexpr bool hasPermutation(std::string_view key) { return findPermutation(key) != nullptr; }

// The float offset of a record input, or ~0u when the permutation's records lack it.
constexpr std::uint32_t recordOffset(const Permutation& p, std::string_view input) {
  for (std::size_t i = 0; i < p.inputCount; ++i)
    if (p.inputs[i].name == input) return p.inputs[i].offset;
  return ~0u;
}
)";

}  // namespace

const nlohmann::json* materialParamsBlock(const nlohmann::json& reflection, int binding) {
  if (!reflection.is_object() || !reflection.contains("uniform_buffers")) return nullptr;
  for (const auto& u : reflection["uniform_buffers"])
    if (u.value("set", -1) == 0 && u.value("binding", -1) == binding) return &u;
  return nullptr;
}

HeaderWriter::HeaderWriter(const PackageInputs& in) : in_(in) {}

void HeaderWriter::add(const PackagedPermutation& p) {
  // The kernel's block; in a package without kernels the fragment shader's, which declares the
  // same members in the same std140 layout (docs/fragment-stage.md).
  const bool kernel = !p.built->spirvHash.empty();
  const nlohmann::json* reflected =
      kernel ? materialParamsBlock(p.built->artifacts.reflection, kKernelParamsBinding)
             : materialParamsBlock(p.built->artifacts.fragment.reflection, kFragmentParamsBinding);
  // No block although the material has run-time parameters: none of them reaches this
  // permutation's output (an occlusion texture without an environment to occlude, every
  // texture of an emission-only permutation), so the optimizer removed the block. The module
  // binds nothing at set 0, binding 2: paramsStruct "" and paramsSize 0 (docs/package.md).
  std::string structName;
  if (reflected) {
    Block b = blockOf(p, *reflected);
    const std::string layout = b.members + b.asserts;
    structName = identifier(p.perm->material->name) + "_Params";
    for (int n = 2; declared_.count(structName) && declared_[structName] != layout; ++n)
      structName = identifier(p.perm->material->name) + "_Params_" + std::to_string(n);
    if (!declared_.count(structName)) {
      declared_[structName] = layout;
      auto [first, fresh] = byLayout_.emplace(layout, structName);
      std::ostringstream decl;
      if (fresh)
        decl << "// std140 block " << (kernel ? "MaterialParamsBlock" : "MbMaterialParams") << " (set 0, binding "
             << (kernel ? kKernelParamsBinding : kFragmentParamsBinding) << ") of material '" << p.perm->material->name
             << "'.\nstruct alignas(16) " << structName << " {\n"
             << b.members << "};\n"
             << replaceName(b.asserts, structName) << "\n";
      else
        decl << "using " << structName << " = " << first->second << ";  // the same block\n\n";
      structs_ += decl.str();
    }
  }
  if (const nlohmann::json* frame = fragmentFrameBlock(p.built->artifacts.fragment.reflection)) {
    // One struct serves every permutation: the block must reflect identically in each.
    if (frame_.empty()) {
      frame_ = frame->dump();
      frameKey_ = p.built->shader.key;
    } else if (frame->dump() != frame_) {
      throw DiagnosticError({{Severity::Error,
                              "E-INTERNAL",
                              {p.built->shader.key, 0, 0},
                              "the fragment shader's MbFrameBlock reflects differently from that of " + frameKey_,
                              ""}});
    }
  }
  const auto fragment = p.fragmentFiles.find("spirv");
  const size_t i = count_++;
  const ProbeLayout& l = p.built->shader.layout;
  std::ostringstream inputs, row;
  inputs << "inline constexpr RecordInput kInputs" << i << "[] = {";
  for (const auto& r : l.inputs)
    inputs << "{" << quoted(r.name) << ", " << r.offset << "u, " << componentCount(r.type) << "u}, ";
  inputs << "};\n";
  inputs_.append(inputs.str());
  row << "    {" << quoted(p.built->shader.key) << ", " << quoted(p.perm->material->name) << ", "
      << quoted(kernel ? p.files.at("spirv") : "") << ", " << quoted(p.include) << ", " << quoted(structName) << ", "
      << (reflected ? reflected->at("size").get<uint64_t>() : 0) << "u, " << l.inStride << "u, " << l.outStride
      << "u, kInputs" << i << ", " << l.inputs.size() << "u, "
      << quoted(fragment == p.fragmentFiles.end() ? "" : fragment->second) << ", "
      << (fragment == p.fragmentFiles.end() ? 0 : fragmentTextures(*p.perm->material).size()) << "u},\n";
  rows_.append(row.str());
}

void HeaderWriter::write(std::ostream& out) const {
  out << "// Generated by matbricks " MB_VERSION " (docs/package.md \"C++ header\"). Do not edit.\n"
      << kPreamble << "namespace " << in_.cppNamespace << " {\n\n"
      << structs_;
  const nlohmann::json frame = frame_.empty() ? nlohmann::json() : nlohmann::json::parse(frame_);
  out << frameBlockHeader(frame_.empty() ? nullptr : &frame, frameKey_) << kTypes;
  inputs_.copyTo(out);
  out << "\ninline constexpr Permutation kPermutations[] = {\n";
  rows_.copyTo(out);
  out << "};\n" << kLookups << "\n}  // namespace " << in_.cppNamespace << "\n";
}

}  // namespace mb
