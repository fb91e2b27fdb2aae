#include "bench/yardstick.hpp"

#include <stdexcept>

#include "common/model_reference.hpp"
#include "common/reference.hpp"

namespace mb::bench {
namespace {

// Model references look bricks up by id in the reference registry (ModelEvalInput::bricks),
// so a composition with ground truths binds each slot to an alias id under which the ground
// truth is registered as a reference. '@' never occurs in a manifest id, so an alias cannot
// shadow a brick; aliases are added once and only by bench.
std::string groundTruthAlias(const std::string& brickId) {
  std::string alias = brickId + "@ground_truth";
  if (!ref::Registry::references().find(alias))
    ref::Registry::references().add(alias, *ref::Registry::groundTruths().find(brickId));
  return alias;
}

}  // namespace

Yardstick brickYardstick(const Brick& brick) {
  Yardstick y;
  if (const ref::Reference* truth = ref::Registry::groundTruths().find(brick.id)) {
    y.kind = "ground_truth";
    y.eval = truth->eval;
  } else if (const ref::Reference* r = ref::Registry::references().find(brick.id)) {
    y.kind = "reference";
    y.eval = r->eval;
  } else {
    throw std::logic_error("brick '" + brick.id + "' has no reference");
  }
  return y;
}

Yardstick materialYardstick(const MaterialDesc& material, const ProbeLayout& layout) {
  ref::ModelReferenceFn model = ref::ModelRegistry::instance().find(material.model);
  if (!model) throw std::logic_error("model '" + material.model + "' has no reference");
  Yardstick y;
  std::map<std::string, std::string> bricks = material.bricks;
  for (auto& [slot, id] : bricks) {
    if (!ref::Registry::groundTruths().find(id)) continue;
    y.groundTruthBricks.push_back(id);
    id = groundTruthAlias(id);
  }
  y.kind = y.groundTruthBricks.empty() ? "reference" : "ground_truth";
  y.eval = [model, layout, bricks, params = material.params](const double* in, double* out) {
    ref::ModelEvalInput e;
    auto at = [&](const std::string& name) { return in + layout.find(name)->offset; };
    e.n = {at("n")[0], at("n")[1], at("n")[2]};
    e.v = {at("v")[0], at("v")[1], at("v")[2]};
    e.l = {at("l")[0], at("l")[1], at("l")[2]};
    e.bricks = bricks;
    for (const auto& p : params)
      e.inputs[p.name] = p.constant ? p.value : std::vector<double>(at(p.name), at(p.name) + componentCount(p.type));
    ref::Vec3 r = model(e);
    out[0] = r.x;
    out[1] = r.y;
    out[2] = r.z;
  };
  return y;
}

}  // namespace mb::bench
