// The library's queries: ShaderLibrary::load (which runs the LibraryLoader of
// library_loader.hpp and reports its diagnostics in reading order), the default root, the
// find*/brickIds/bricksOfSlot look-ups, the cached GLSL sources and their display paths, and
// the light types and environment modes every model draws from.
#include "library/shader_library.hpp"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <tuple>

#include "core/data_dir.hpp"
#include "library/library_loader.hpp"

namespace mb {

namespace fs = std::filesystem;

namespace {

// Guards the source cache: emit may run on several threads over one library.
std::mutex& sourceCacheMutex() {
  static std::mutex m;
  return m;
}

}  // namespace

// Files in the order they were read, positions in file order within each: the checks of
// one brick do not run in the order its fields are written.
static std::vector<Diagnostic> inReadingOrder(std::vector<Diagnostic> diags) {
  std::vector<std::string> files;
  for (const auto& d : diags)
    if (std::find(files.begin(), files.end(), d.where.file) == files.end()) files.push_back(d.where.file);
  auto rank = [&](const Diagnostic& d) {
    auto index = std::find(files.begin(), files.end(), d.where.file) - files.begin();
    return std::make_tuple(index, d.where.line, d.where.column);
  };
  std::stable_sort(diags.begin(), diags.end(),
                   [&](const Diagnostic& a, const Diagnostic& b) { return rank(a) < rank(b); });
  return diags;
}

ShaderLibrary ShaderLibrary::load(const fs::path& root) {
  DiagnosticSink sink;
  LibraryData data = LibraryLoader(root, sink).run();
  if (sink.hasErrors()) throw DiagnosticError(inReadingOrder(sink.all()));
  ShaderLibrary lib;
  lib.root_ = root;
  lib.units_ = std::move(data.units);
  lib.slots_ = std::move(data.slots);
  lib.bricks_ = std::move(data.bricks);
  lib.models_ = std::move(data.models);
  lib.roughnessKinds_ = std::move(data.roughnessKinds);
  lib.gltfDefaults_ = std::move(data.gltfDefaults);
  // Every GLSL file was read during validation; keep it so source() rarely touches disk.
  lib.sources_ = std::move(data.sources);
  return lib;
}

fs::path ShaderLibrary::defaultRoot() {
  const char* env = std::getenv("MATBRICKS_SHADERLIB");
  if (env && *env) return fs::path(env);
  return dataRoot() / "shaderlib";
}

template <class T, class Key>
static const T* findBy(const std::vector<T>& items, const std::string& key, Key T::*member) {
  auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.*member == key; });
  return it == items.end() ? nullptr : &*it;
}

const Slot* ShaderLibrary::findSlot(const std::string& name) const { return findBy(slots_, name, &Slot::name); }

const Brick* ShaderLibrary::findBrick(const std::string& id) const { return findBy(bricks_, id, &Brick::id); }

const ShadingModel* ShaderLibrary::findModel(const std::string& name) const {
  return findBy(models_, name, &ShadingModel::name);
}

const ModelRole* ShadingModel::findRole(const std::string& role) const { return findBy(roles, role, &ModelRole::role); }

const ModelFeature* ShadingModel::findFeature(const std::string& feature) const {
  return findBy(features, feature, &ModelFeature::name);
}

const LightMethodChoice* ShadingModel::findLightMethod(LightType light) const {
  auto it = std::find_if(lightMethods.begin(), lightMethods.end(),
                         [&](const LightMethodChoice& c) { return c.light == light; });
  return it == lightMethods.end() ? nullptr : &*it;
}

std::vector<std::string> ShadingModel::coreRoles() const {
  std::vector<std::string> out;
  for (const auto& r : roles)
    if (r.feature.empty() && r.lights.empty() && r.environments.empty()) out.push_back(r.role);
  return out;
}

const Unit* ShaderLibrary::findUnit(const std::string& id) const { return findBy(units_, id, &Unit::id); }

std::vector<std::string> ShaderLibrary::brickIds() const {
  std::vector<std::string> ids;
  for (const auto& b : bricks_) ids.push_back(b.id);
  return ids;
}

std::vector<std::string> ShaderLibrary::bricksOfSlot(const std::string& slot) const {
  std::vector<std::string> ids;
  for (const auto& b : bricks_)
    if (b.slot == slot) ids.push_back(b.id);
  return ids;
}

const Brick* ShaderLibrary::brickForKernelRole(const std::string& role) const {
  for (const auto& b : bricks_)
    if (std::find(b.kernelRoles.begin(), b.kernelRoles.end(), role) != b.kernelRoles.end()) return &b;
  return nullptr;
}

RoughnessKind ShaderLibrary::roughnessKind(const std::string& inputName) const {
  auto it = roughnessKinds_.find(inputName);
  return it == roughnessKinds_.end() ? RoughnessKind::None : it->second;
}

const std::string& ShaderLibrary::source(const std::string& relativeFile) const {
  std::lock_guard<std::mutex> lock(sourceCacheMutex());
  auto it = sources_.find(relativeFile);
  if (it != sources_.end()) return it->second;
  auto text = readFile(root_ / relativeFile);
  if (!text) {
    throw DiagnosticError({{Severity::Error,
                            "E-FILE-NOT-FOUND",
                            {displayPath(relativeFile), 0, 0},
                            "cannot read shader library file '" + (root_ / relativeFile).string() + "'",
                            ""}});
  }
  // std::map never moves its nodes, so the returned reference stays valid.
  return sources_.emplace(relativeFile, std::move(*text)).first->second;
}

std::string ShaderLibrary::displayPath(const std::string& relativeFile) { return "shaderlib/" + relativeFile; }

}  // namespace mb
