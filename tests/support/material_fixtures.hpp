// Shared by the description-form tests (test_loader.cpp, test_macro_form.cpp): a fake library
// whose model has features, conditional roles and feature inputs, a scratch project folder,
// and helpers to catch diagnostics.
#pragma once
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "../fake_library.hpp"
#include "library/shader_library.hpp"
#include "load/material_desc.hpp"

namespace mb::test {

// The fake library's `standard` with two features (docs/models.md): `clearcoat` (a role with a
// default, an input) and `sheen` (a role without a default, a vec3 input), plus an
// environment-conditional role with a default.
inline const char* kFeatureModelJson = R"({
  "name": "standard",
  "description": "test model with features",
  "skeleton": "standard.glsl",
  "requires": ["common"],
  "lights": ["dir", "point"],
  "environments": ["none", "ibl_lut"],
  "features": [
    {"name": "clearcoat", "description": "coat"},
    {"name": "sheen", "description": "sheen"}
  ],
  "roles": [
    {"role": "specular_d", "slot": "specular_d", "description": "D"},
    {"role": "fresnel", "slot": "fresnel", "description": "F"},
    {"role": "env_fresnel", "slot": "fresnel", "default": "f_schlick", "environments": ["ibl_lut"], "description": "F of IBL"},
    {"role": "clearcoat_d", "slot": "specular_d", "default": "d_ggx", "feature": "clearcoat", "description": "coat D"},
    {"role": "sheen_d", "slot": "specular_d", "feature": "sheen", "description": "sheen D, no default"}
  ],
  "inputs": [
    {"name": "baseColor", "type": "vec3", "default": [0.8, 0.8, 0.8], "range": [0.0, 1.0], "description": "albedo"},
    {"name": "metallic", "type": "float", "default": 0.0, "range": [0.0, 1.0], "description": "metalness"},
    {"name": "roughness", "type": "float", "default": 0.5, "range": [0.0, 1.0], "description": "perceptual roughness"},
    {"name": "clearCoat", "type": "float", "default": 1.0, "range": [0.0, 1.0], "feature": "clearcoat", "neutral": 0.0, "description": "coat strength"},
    {"name": "sheenColor", "type": "vec3", "default": [0.5, 0.5, 0.5], "range": [0.0, 1.0], "feature": "sheen", "neutral": [0.0, 0.0, 0.0], "description": "sheen"}
  ]
}
)";

inline const ShaderLibrary& featureLibrary() {
  static FakeLibrary files(std::map<std::string, std::string>{{"models/standard.json", kFeatureModelJson}});
  static ShaderLibrary lib = ShaderLibrary::load(files.root());
  return lib;
}

// A folder for material files, removed on destruction.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : root_(std::filesystem::temp_directory_path() / ("mb_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(root_);
    std::filesystem::create_directories(root_);
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(root_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  std::string path(const std::string& relative) const { return (root_ / relative).string(); }
  std::string write(const std::string& relative, const std::string& text) const {
    std::filesystem::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative, std::ios::binary) << text;
    return path(relative);
  }

 private:
  std::filesystem::path root_;
};

// The diagnostics `load` throws (empty if it does not throw).
inline std::vector<Diagnostic> diagnosticsOf(const std::function<void()>& load) {
  try {
    load();
  } catch (const DiagnosticError& e) {
    return e.diagnostics();
  }
  return {};
}

// The one diagnostic with `code`; fails the test when there is not exactly one.
inline Diagnostic theOne(const std::vector<Diagnostic>& ds, const std::string& code) {
  std::vector<Diagnostic> hits;
  for (const auto& d : ds)
    if (d.code == code) hits.push_back(d);
  INFO("diagnostics:\n" << (ds.empty() ? std::string("(none)") : DiagnosticError(ds).what()));
  REQUIRE(hits.size() == 1);
  return hits.front();
}

inline void requireAt(const Diagnostic& d, const std::string& file, int line, int column) {
  INFO(formatDiagnostic(d));
  CHECK(d.where.file == file);
  CHECK(d.where.line == line);
  CHECK(d.where.column == column);
}

// Field-by-field equality of what two descriptions mean (not where they were written):
// everything but sourceFile, form, locations and warnings.
inline void requireSameMaterial(const MaterialDesc& a, const MaterialDesc& b) {
  CHECK(a.name == b.name);
  CHECK(a.model == b.model);
  CHECK(a.description == b.description);
  CHECK(a.features == b.features);
  CHECK(a.bricks == b.bricks);
  CHECK(a.surface.glsl == b.surface.glsl);
  REQUIRE(a.params.size() == b.params.size());
  for (size_t i = 0; i < a.params.size(); ++i) {
    INFO("parameter " << i << ": " << a.params[i].name);
    CHECK(a.params[i].name == b.params[i].name);
    CHECK(a.params[i].type == b.params[i].type);
    CHECK(a.params[i].value == b.params[i].value);
    CHECK(a.params[i].constant == b.params[i].constant);
    CHECK(a.params[i].range.lo == b.params[i].range.lo);
    CHECK(a.params[i].range.hi == b.params[i].range.hi);
    CHECK(a.params[i].user == b.params[i].user);
  }
}

}  // namespace mb::test
