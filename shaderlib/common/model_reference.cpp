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

double ModelEvalInput::floatInput(const std::string& name) const {
  auto it = inputs.find(name);
  if (it == inputs.end() || it->second.size() != 1)
    throw std::logic_error("model input '" + name + "' missing or not a float");
  return it->second[0];
}

Vec3 ModelEvalInput::vec3Input(const std::string& name) const {
  auto it = inputs.find(name);
  if (it == inputs.end() || it->second.size() != 3)
    throw std::logic_error("model input '" + name + "' missing or not a vec3");
  return {it->second[0], it->second[1], it->second[2]};
}

static const Reference& boundReference(const ModelEvalInput& in, const std::string& role) {
  auto b = in.bricks.find(role);
  if (b == in.bricks.end()) throw std::logic_error("no brick bound to role '" + role + "'");
  if (in.groundTruths)
    if (const Reference* truth = Registry::groundTruths().find(b->second)) return *truth;
  const Reference* r = Registry::references().find(b->second);
  if (!r) throw std::logic_error("brick '" + b->second + "' has no reference");
  return *r;
}

double ModelEvalInput::scalar(const std::string& role, const Args& args) const {
  double out = 0;
  boundReference(*this, role).eval(args.values.data(), &out);
  return out;
}

Vec3 ModelEvalInput::vec3(const std::string& role, const Args& args) const {
  double out[3] = {0, 0, 0};
  boundReference(*this, role).eval(args.values.data(), out);
  return {out[0], out[1], out[2]};
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
