#include "bench_engine/yardstick.hpp"

#include <optional>
#include <stdexcept>

#include "common/reference.hpp"
#include "validate/probe_program.hpp"

namespace mb::bench {

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

namespace {

std::optional<Diagnostic> unmeasurable(const MaterialDesc& material) {
  if (!material.surface.present()) return std::nullopt;
  return Diagnostic(Severity::Error, "E-BENCH-SURFACE", material.surface.where,
                    "bench cannot measure material '" + material.name +
                        "': its user surface code has no C++ form to take ground truths of",
                    "bench the material without its surface code");
}

}  // namespace

void refuseUnmeasurable(const std::vector<MaterialDesc>& materials) {
  std::vector<Diagnostic> errors;
  for (const auto& material : materials)
    if (auto d = unmeasurable(material)) errors.push_back(*d);
  if (!errors.empty()) throw DiagnosticError(errors);
}

Yardstick materialYardstick(const MaterialDesc& material, const ProbeLayout& layout,
                            std::shared_ptr<const ProbeLtcTable> ltcTable) {
  if (auto d = unmeasurable(material)) throw DiagnosticError({*d});
  Yardstick y;
  for (const auto& [slot, id] : material.bricks)
    if (ref::Registry::groundTruths().find(id)) y.groundTruthBricks.push_back(id);
  y.kind = y.groundTruthBricks.empty() ? "reference" : "ground_truth";
  Permutation perm;  // the material's default permutation: the one bench times
  perm.material = &material;
  y.eval = materialReferenceEval(perm, layout, material.bricks, /*groundTruths=*/true, false, ReferenceLookup::Resolved,
                                 std::move(ltcTable));
  return y;
}

}  // namespace mb::bench
