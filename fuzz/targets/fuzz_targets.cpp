#include "fuzz_targets.hpp"

#include <filesystem>
#include <fstream>
#include <typeinfo>
#include <unistd.h>

#include "core/data_dir.hpp"
#include "core/diagnostics.hpp"
#include "library/shader_library.hpp"
#include "load/csv_table.hpp"
#include "load/gltf_import.hpp"
#include "load/material_desc.hpp"
#include "load/material_resolve.hpp"
#include "load/scene_desc.hpp"
#include "permute/scene_plan.hpp"

namespace mb::fuzz {

namespace fs = std::filesystem;

namespace {

const ShaderLibrary& library() {
  static const ShaderLibrary lib = ShaderLibrary::load(ShaderLibrary::defaultRoot());
  return lib;
}

std::string text(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }

}  // namespace

// Success, or a DiagnosticError whose every error names its code and its file, is what the
// loaders promise (docs/bad-inputs.md); everything else is a finding.
void expectLoadOrDiagnostics(const std::function<void()>& load) {
  try {
    load();
  } catch (const DiagnosticError& e) {
    if (e.diagnostics().empty()) throw FuzzFinding("DiagnosticError without diagnostics");
    bool anyError = false;
    for (const auto& d : e.diagnostics()) {
      if (d.severity != Severity::Error) continue;
      anyError = true;
      if (d.code.rfind("E-", 0) != 0) throw FuzzFinding("error without an E- code: " + formatDiagnostic(d));
      if (d.where.file.empty()) throw FuzzFinding("error without a file: " + formatDiagnostic(d));
    }
    if (!anyError) throw FuzzFinding("DiagnosticError holding only warnings");
  } catch (const FuzzFinding&) {
    throw;
  } catch (const std::exception& e) {
    throw FuzzFinding(std::string("unexpected ") + typeid(e).name() + ": " + e.what());
  }
}

namespace {

// A project directory for the macro form's #include: the fuzzed file is read as
// <dir>/fuzz.mat, beside two include files that the seeds and the dictionary name. Made once
// per process in the temporary directory and removed at exit.
class MacroProject {
 public:
  MacroProject() {
    dir_ = fs::temp_directory_path() / ("matbricks-fuzz-macro-" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "inc");
    std::ofstream(dir_ / "common.mat") << "#define BRICK_diffuse diffuse_lambert\n"
                                          "#define PARAM_tint vec3(0.5, 0.5, 0.5) RANGE(0.0, 1.0)\n";
    std::ofstream(dir_ / "inc" / "surface.glsl")
        << "void surface(inout MaterialInputs m, MaterialParams p) { m.baseColor = p.tint; }\n";
  }
  ~MacroProject() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string file() const { return (dir_ / "fuzz.mat").string(); }

 private:
  fs::path dir_;
};

void materialJson(const uint8_t* data, size_t size) {
  expectLoadOrDiagnostics([&] { parseMaterialJson(text(data, size), "fuzz.json", library()); });
}

void materialMacro(const uint8_t* data, size_t size) {
  static const MacroProject project;
  expectLoadOrDiagnostics([&] { parseMaterialMacro(text(data, size), project.file(), library()); });
}

// .gltf or .glb by content, as the CLI does; then every material resolved against the library
// like importGltfMaterials, from memory. URIs resolve against examples/gltf/ (read only).
void gltf(const uint8_t* data, size_t size) {
  static const std::string file = (dataRoot() / "examples" / "gltf" / "fuzz.gltf").string();
  expectLoadOrDiagnostics([&] {
    std::vector<GltfMaterial> materials = parseGltf(text(data, size), file, library());
    DiagnosticSink sink;
    for (const auto& m : materials) resolveMaterialInto(m.source, library(), sink);
    throwInFileOrder(sink, file);
  });
}

// Scene JSON, read and planned; material paths resolve against examples/scenes/ (read only).
void scene(const uint8_t* data, size_t size) {
  static const std::string file = (dataRoot() / "examples" / "scenes" / "fuzz.json").string();
  expectLoadOrDiagnostics([&] { planScene(parseSceneJson(text(data, size), file, library()), library()); });
}

// The CSV of `matbricks eval`, with the columns of a brick of n, v, l and alpha (d_ggx).
void csv(const uint8_t* data, size_t size) {
  expectLoadOrDiagnostics([&] {
    selectColumns(parseCsv(text(data, size), "fuzz.csv"),
                  {"n.x", "n.y", "n.z", "v.x", "v.y", "v.z", "l.x", "l.y", "l.z", "alpha"});
  });
}

}  // namespace

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"material_json", materialJson},
      {"material_macro", materialMacro},
      {"gltf", gltf},
      {"scene", scene},
      {"csv", csv},
  };
  return all;
}

const Target& target(const std::string& name) {
  for (const auto& t : targets())
    if (name == t.name) return t;
  throw std::invalid_argument("no fuzz target '" + name + "'");
}

}  // namespace mb::fuzz
