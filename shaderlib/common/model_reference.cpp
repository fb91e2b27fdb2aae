#include "common/model_reference.hpp"

#include <stdexcept>

namespace mb::ref {

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

static const Reference& boundReference(const ModelEvalInput& in, const std::string& slot) {
  auto b = in.bricks.find(slot);
  if (b == in.bricks.end()) throw std::logic_error("no brick bound to slot '" + slot + "'");
  if (in.groundTruths)
    if (const Reference* truth = Registry::groundTruths().find(b->second)) return *truth;
  const Reference* r = Registry::references().find(b->second);
  if (!r) throw std::logic_error("brick '" + b->second + "' has no reference");
  return *r;
}

static std::vector<double> pack(const ModelEvalInput& in, std::initializer_list<double> args,
                                bool withGeometry, std::initializer_list<double> tail) {
  std::vector<double> p(args);
  if (withGeometry) {
    for (const Vec3& v : {in.n, in.v, in.l}) p.insert(p.end(), {v.x, v.y, v.z});
  }
  p.insert(p.end(), tail);
  return p;
}

double ModelEvalInput::callScalar(const std::string& slot, std::initializer_list<double> args,
                                  bool withGeometry, std::initializer_list<double> tail) const {
  auto p = pack(*this, args, withGeometry, tail);
  double out = 0;
  boundReference(*this, slot).eval(p.data(), &out);
  return out;
}

Vec3 ModelEvalInput::callVec3(const std::string& slot, std::initializer_list<double> args,
                              bool withGeometry, std::initializer_list<double> tail) const {
  auto p = pack(*this, args, withGeometry, tail);
  double out[3] = {0, 0, 0};
  boundReference(*this, slot).eval(p.data(), out);
  return {out[0], out[1], out[2]};
}

ModelRegistry& ModelRegistry::instance() {
  static ModelRegistry r;
  return r;
}

bool ModelRegistry::add(const std::string& model, ModelReferenceFn fn) {
  if (!entries_.emplace(model, fn).second)
    throw std::logic_error("duplicate model reference '" + model + "'");
  return true;
}

ModelReferenceFn ModelRegistry::find(const std::string& model) const {
  auto it = entries_.find(model);
  return it == entries_.end() ? nullptr : it->second;
}

}  // namespace mb::ref
