// A small, fixed shader library written to a temporary folder, for loader and library tests.
// The shipped library grows while the project is built; tests that assert exact messages
// ("one of 'd_ggx', 'd_beckmann'") need a library whose content they control.
#pragma once
#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>

#include "core/diagnostics.hpp"

namespace mb::test {

// Default file contents. Individual tests replace single files to inject a mistake.
inline std::map<std::string, std::string> fakeLibraryFiles() {
  return {
      {"manifest.json", R"({
  "schema": 1,
  "units": [{"id": "common", "file": "common/common.glsl"}],
  "slots": ["specular_d", "fresnel"],
  "models": ["standard"]
}
)"},
      {"common/common.glsl", "struct Geometry { vec3 n; vec3 v; vec3 l; };\n"},
      {"specular_d/slot.json", R"({
  "name": "specular_d",
  "description": "NDF",
  "returns": "float",
  "params": [{"name": "g", "type": "Geometry"}, {"name": "alpha", "type": "float"}],
  "bricks": [
    {
      "id": "d_ggx",
      "name": "GGX",
      "function": "mb_d_ggx",
      "file": "d_ggx.glsl",
      "citation": "Walter et al. 2007",
      "requires": ["common"],
      "domain": {"alpha": [0.002, 1.0]},
      "geometry": {"NoV": [0.01, 1.0]},
      "tolerance": {"abs": 0.0, "rel": 5e-4, "reason": "fp32 half vector"}
    },
    {
      "id": "d_beckmann",
      "name": "Beckmann",
      "function": "mb_d_beckmann",
      "file": "d_beckmann.glsl",
      "citation": "Beckmann 1963",
      "requires": [],
      "domain": {"alpha": [0.01, 1.0]},
      "tolerance": {"abs": 1e-6, "rel": 1e-4, "reason": "exp in fp32"},
      "notes": "test brick"
    }
  ]
}
)"},
      {"specular_d/d_ggx.glsl", "float mb_d_ggx(Geometry g, float alpha) { return alpha; }\n"},
      {"specular_d/d_beckmann.glsl", "float mb_d_beckmann (Geometry g, float alpha) { return alpha; }\n"},
      {"fresnel/slot.json", R"({
  "name": "fresnel",
  "description": "Fresnel",
  "returns": "vec3",
  "params": [{"name": "g", "type": "Geometry"}, {"name": "f0", "type": "vec3"}],
  "bricks": [
    {
      "id": "f_schlick",
      "name": "Schlick",
      "function": "mb_f_schlick",
      "file": "f_schlick.glsl",
      "citation": "Schlick 1994",
      "requires": ["common"],
      "domain": {"f0": [0.0, 1.0]},
      "tolerance": {"abs": 1e-6, "rel": 1e-6, "reason": "pow5"}
    }
  ]
}
)"},
      {"fresnel/f_schlick.glsl", "vec3 mb_f_schlick(Geometry g, vec3 f0) { return f0; }\n"},
      {"models/standard.json", R"({
  "name": "standard",
  "description": "test model",
  "skeleton": "standard.glsl",
  "requires": ["common"],
  "lights": ["dir"],
  "environments": ["none"],
  "roles": [
    {"role": "specular_d", "slot": "specular_d", "description": "D"},
    {"role": "fresnel", "slot": "fresnel", "description": "F"}
  ],
  "inputs": [
    {"name": "baseColor", "type": "vec3", "default": [0.8, 0.8, 0.8], "range": [0.0, 1.0], "description": "albedo"},
    {"name": "metallic", "type": "float", "default": 0.0, "range": [0.0, 1.0], "description": "metalness"},
    {"name": "roughness", "type": "float", "default": 0.5, "range": [0.0, 1.0], "description": "perceptual roughness"}
  ]
}
)"},
      {"models/standard.glsl", "// skeleton\n"},
  };
}

// Writes a library to a fresh temporary folder and removes it again on destruction.
class FakeLibrary {
 public:
  explicit FakeLibrary(const std::map<std::string, std::string>& overrides = {}) {
    static std::atomic<int> counter{0};
    root_ = std::filesystem::temp_directory_path() /
            ("mb_fake_lib_" + std::to_string(std::random_device{}()) + "_" + std::to_string(counter++));
    auto files = fakeLibraryFiles();
    for (const auto& [path, text] : overrides) files[path] = text;
    for (const auto& [path, text] : files) {
      if (text.empty()) continue;  // an empty override deletes the file
      write(path, text);
    }
  }
  ~FakeLibrary() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  FakeLibrary(const FakeLibrary&) = delete;
  FakeLibrary& operator=(const FakeLibrary&) = delete;

  const std::filesystem::path& root() const { return root_; }
  // The path diagnostics use for a library file.
  std::string path(const std::string& relative) const { return (root_ / relative).lexically_normal().string(); }
  void write(const std::string& relative, const std::string& text) const {
    std::filesystem::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative, std::ios::binary) << text;
  }

 private:
  std::filesystem::path root_;
};

}  // namespace mb::test
