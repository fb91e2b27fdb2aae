// write: the parts of an engine-ready package (docs/package.md), each built by its own file:
//   glsl_include.cpp   include/<key>.glsl
//   manifest_json.cpp  manifest.json
//   cpp_header.cpp     the C++17 header
// package_contents.cpp decides the file names (deduplicated by SPIR-V hash) and adds them.
#pragma once
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "write/package_contents.hpp"
#include "write/spill_file.hpp"

namespace mb {

struct PackagedPermutation {
  const Permutation* perm = nullptr;
  const BuiltPermutation* built = nullptr;
  std::map<std::string, std::string> files;     // target -> path in the package ("spirv/<hash>.spv")
  std::string include;                          // "include/<key>.glsl"
  std::map<std::string, std::string> includes;  // "glsl", "hlsl", "msl" -> path of that include
  // target -> path of the fragment shader ("fragment/spirv/<hash>.spv"); empty: none built
  std::map<std::string, std::string> fragmentFiles;
};

// The fragment stage's parts (fragment_parts.cpp, docs/fragment-stage.md):
// its file in the package, "fragment/<target>/<hash><fragmentExtension>";
std::string fragmentPath(const std::string& target, const std::string& hash);
// the manifest's per-permutation "fragment" object and top-level "fragment" interface;
nlohmann::json fragmentEntryJson(const PackagedPermutation& p);
nlohmann::json fragmentInterfaceJson();
// the frame block (set 0, binding 1) in a fragment module's reflection, or null;
const nlohmann::json* fragmentFrameBlock(const nlohmann::json& reflection);
// the header's binding constants and light records, and, given the reflected frame block,
// MbFrameBlock with static_asserts on its offsets and size (E-INTERNAL naming `key` if the
// block is not engine_frame.glsl's).
std::string frameBlockHeader(const nlohmann::json* reflected, const std::string& key);

// The emitted GLSL up to the probe, as a self-contained include: no #version, #extension or
// #line (each #line becomes a "// from <file>:<line>" comment), an include guard and a header
// comment naming the hooks the engine defines and the entry points it gets.
std::string engineInclude(const PackagedPermutation& p);
// The HLSL or MSL include (target "hlsl" or "msl") around its body from the build
// (compile/engine_includes.hpp): header comment with the exact signatures, include guard.
std::string crossInclude(const PackagedPermutation& p, const std::string& target, const std::string& body);
// "include/<key>.hlsl" or "include/<key>.metal".
std::string crossIncludePath(const std::string& key, const std::string& target);
// Shared by the includes: the guard macro (MB_INCLUDE_<KEY><SUFFIX>) and the first comment
// lines naming the permutation.
std::string includeGuard(const std::string& key, const std::string& suffix);
std::string includeOrigin(const PackagedPermutation& p, const std::string& language);
// Whether the permutation's environment calls the engine's fetch hooks (IBL modes).
bool needsFetchHooks(const Permutation& perm);

// The Engine record layout (offsets in floats) as the manifest stores it.
nlohmann::json recordLayoutJson(const ProbeLayout& layout);

// manifest.json, one permutation at a time: each entry is printed when added and kept in a
// spill file, so memory stays flat at any package size. write() gives the bytes nlohmann's
// dump(2) gives for the whole document (sorted keys, 2-space indent).
class ManifestWriter {
 public:
  explicit ManifestWriter(const PackageInputs& in);
  void add(const PackagedPermutation& p);
  void write(std::ostream& out) const;

 private:
  const PackageInputs& in_;
  std::set<std::string> hashes_;
  size_t count_ = 0;
  SpillFile entries_;
};

// The C++17 header, one permutation at a time; its struct offsets come from each module's
// SPIRV-Cross reflection. Only the distinct parameter structs stay in memory.
class HeaderWriter {
 public:
  explicit HeaderWriter(const PackageInputs& in);
  void add(const PackagedPermutation& p);
  void write(std::ostream& out) const;

 private:
  const PackageInputs& in_;
  std::map<std::string, std::string> byLayout_;  // members + asserts -> struct name
  std::map<std::string, std::string> declared_;  // struct name -> layout, to detect clashes
  std::string frame_, frameKey_;                 // the first fragment shader's MbFrameBlock, its key
  std::string structs_;
  size_t count_ = 0;
  SpillFile inputs_, rows_;
};

// The material parameter block at set 0, `binding` (the kernel's kKernelParamsBinding, the
// fragment shader's kFragmentParamsBinding) in a module's reflection, or null.
const nlohmann::json* materialParamsBlock(const nlohmann::json& reflection, int binding);

}  // namespace mb
