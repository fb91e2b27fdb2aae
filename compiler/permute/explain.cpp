// `compile --explain` (docs/scenes.md "Explain"): the counts, the axes that multiplied them,
// and per material what was folded, what was kept and why, and what quality changed.
#include <cstdio>
#include <sstream>

#include "permute/scene_plan.hpp"

namespace mb {

namespace {

std::string axesText(const std::vector<AxisSize>& axes, const std::string& joiner) {
  std::string s;
  for (const auto& a : axes) s += (s.empty() ? "" : joiner) + a.axis + " x" + std::to_string(a.values);
  return s;
}

std::string row(const std::string& label, size_t n, const std::string& why) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%-10s %6zu", label.c_str(), n);
  return std::string(buf) + (why.empty() ? "" : "   (" + why + ")") + "\n";
}

}  // namespace

std::string explainText(const ScenePlan& plan, size_t compiled, size_t uniqueSpirv, const std::string& compiledHow) {
  std::ostringstream out;
  const size_t materials = plan.notes.size();
  std::string m = std::to_string(materials) + (materials == 1 ? " material" : " materials");
  size_t full = 1;
  for (const auto& a : plan.possibleAxes) full *= a.values;
  out << row("possible", plan.possible,
             "valid points summed over " + m + "; the largest model's product: " + axesText(plan.possibleAxes, ", ") +
                 " = " + std::to_string(full) + " before validity");
  std::string req = m;
  for (const auto& a : plan.requiredAxes) req += " x " + a.axis + " x" + std::to_string(a.values);
  out << row("required", plan.required.size(), req);
  out << row("compiled", compiled, compiled == plan.required.size() ? compiledHow : "DIFFERS from required");
  out << row("unique", uniqueSpirv, "by SPIR-V hash");
  for (const auto& n : plan.notes) {
    out << "material " << n.material << ":";
    out << "\n";
    for (const auto& f : n.folded) out << "  folded " << f << ": every use holds it at its neutral value\n";
    if (!n.absent.empty()) {
      out << "  absent";
      for (const auto& f : n.absent) out << " " << f;
      out << ": the material does not enable them (no lobe emitted)\n";
    }
    for (const auto& [f, why] : n.keptReasons) out << "  kept   " << f << ": " << why << "\n";
    for (const auto& [levelRole, brick] : n.qualityBricks) out << "  quality " << levelRole << " -> " << brick << "\n";
  }
  return out.str();
}

}  // namespace mb
