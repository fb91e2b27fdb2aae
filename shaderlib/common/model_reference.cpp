#include "common/model_reference.hpp"

#include <stdexcept>

namespace mb::ref {

double probeEnvironmentShape(const Vec3& r, double lod) {
  // probe_scene.glsl's mb_probe_environment_shape: positive for unit r and lod >= 0, and
  // varied enough that a wrong reflection vector or mip level shows.
  return (1.5 + 0.5 * r.x + 0.25 * r.y - 0.125 * r.z) * (1.0 + 0.125 * lod);
}

Vec3 Environment::prefilteredAt(const Vec3& r, double lod) const {
  return fetchPrefiltered ? fetchPrefiltered(r, lod) : prefiltered * probeEnvironmentShape(r, lod);
}

void Args::overflow() { throw std::logic_error("brick call with more than Args::kCapacity doubles"); }

double ModelEvalInput::floatInputByName(const std::string& name) const {
  auto it = inputs.find(name);
  if (it == inputs.end() || it->second.size() != 1)
    throw std::logic_error("model input '" + name + "' missing or not a float");
  return it->second[0];
}

Vec3 ModelEvalInput::vec3InputByName(const std::string& name) const {
  auto it = inputs.find(name);
  if (it == inputs.end() || it->second.size() != 3)
    throw std::logic_error("model input '" + name + "' missing or not a vec3");
  return {it->second[0], it->second[1], it->second[2]};
}

// The brick bound to `role`: its ground truth when asked for and registered, else its
// reference.
static const Reference* boundReference(const std::map<std::string, std::string>& bricks, bool groundTruths,
                                       const std::string& role) {
  auto b = bricks.find(role);
  if (b == bricks.end()) return nullptr;
  if (groundTruths)
    if (const Reference* truth = Registry::groundTruths().find(b->second)) return truth;
  return Registry::references().find(b->second);
}

const Reference& ModelEvalInput::referenceByName(const std::string& role) const {
  if (const Reference* r = boundReference(bricks, groundTruths, role)) return *r;
  auto b = bricks.find(role);
  if (b == bricks.end()) throw std::logic_error("no brick bound to role '" + role + "'");
  throw std::logic_error("brick '" + b->second + "' has no reference");
}

void ModelEvalInput::resolve() {
  plan_ = Plan{};
  for (size_t i = 0; i < std::size(names::kRoles); ++i)
    plan_.roles[i] = boundReference(bricks, groundTruths, std::string(names::kRoles[i]));
  for (const auto& [name, value] : inputs) {
    const int i = names::find(names::kInputs, name);
    // An input no reference reads (a user parameter) is not kept; a size other than 1 or 3
    // is left unset, so that reading it throws as on the unresolved path.
    if (i >= 0 && (value.size() == 1 || value.size() == 3)) setInput(i, value.data(), static_cast<int>(value.size()));
  }
  for (size_t i = 0; i < std::size(names::kFeatures); ++i)
    if (features.count(std::string(names::kFeatures[i]))) plan_.features |= 1u << i;
  resolved_ = true;
}

ModelRegistry& ModelRegistry::instance() {
  static ModelRegistry r;
  return r;
}

bool ModelRegistry::add(const std::string& model, ModelReferenceFn fn) {
  if (!entries_.emplace(model, fn).second) throw std::logic_error("duplicate model reference '" + model + "'");
  return true;
}

ModelReferenceFn ModelRegistry::find(const std::string& model) const {
  auto it = entries_.find(model);
  return it == entries_.end() ? nullptr : it->second;
}

}  // namespace mb::ref
