// Rendering of the energy report: JSON (everything, per cell), text (summaries) and Markdown
// (docs/energy.md: summaries, the GGX albedo and compensation grids, notes per lobe).
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "energy/energy_checks.hpp"

namespace mb::energy {
namespace {

std::string fmt(const char* f, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

double minAlbedo(const LobeAlbedo& a) {
  double m = INFINITY;
  for (const auto& c : a.cells) m = std::min(m, c.gpu);
  return m;
}

double maxAbsMismatch(const LobeAlbedo& a) {
  double m = 0;
  for (const auto& c : a.cells) m = std::max(m, std::abs(c.gpu - c.reference));
  return m;
}

std::string furnaceVerdict(const LobeAlbedo& a) {
  const AlbedoCell& m = a.maxCell();
  if (!a.exceedsOne()) return "<= 1";
  return fmt("exceeds 1 by %.4f at n.v = %g, r = %g", m.gpu - 1.0, m.NoV, m.perceptualRoughness);
}

std::string gridLine(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + fmt("%g", x);
  return s;
}

// One row per lobe of the kinds in `kinds`.
std::string furnaceTable(const EnergyReport& r, bool diffuse) {
  std::string s =
      "| lobe | theory | max albedo | at (n.v, r) | min albedo | max \\|GPU - ref\\| | max \\|GPU - ref\\| / bound | "
      "quadrature \\|A(N) - A(N/2)\\| | verdict |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const LobeAlbedo& a : r.furnace) {
    if ((a.lobe->kind == LobeKind::Diffuse) != diffuse) continue;
    const AlbedoCell& m = a.maxCell();
    s += fmt("| `%s` | %s | %.6f | (%g, %g) | %.6f | %.1e | %.3f | %.1e | %s |\n", a.lobe->name.c_str(),
             expectationName(a.lobe->expectation), m.gpu, m.NoV, m.perceptualRoughness, minAlbedo(a), maxAbsMismatch(a),
             a.maxMismatchRatio(), a.maxConvergence(), furnaceVerdict(a).c_str());
  }
  return s;
}

// A (n.v rows) x (roughness columns) table of value(cell index).
template <class Fn>
std::string gridTable(const EnergyGrid& g, const char* corner, Fn&& value) {
  std::string s = fmt("| %s |", corner), sep = "|---|";
  for (double r : g.perceptualRoughness) {
    s += fmt(" r = %g |", r);
    sep += "---|";
  }
  s += "\n" + sep + "\n";
  for (size_t i = 0; i < g.NoV.size(); ++i) {
    s += fmt("| n.v = %g |", g.NoV[i]);
    for (size_t j = 0; j < g.perceptualRoughness.size(); ++j)
      s += " " + value(i * g.perceptualRoughness.size() + j) + " |";
    s += "\n";
  }
  return s;
}

std::string reciprocityTable(const EnergyReport& r) {
  std::string s =
      "| lobe | interior pairs | GPU asymmetry | reference asymmetry | GPU asymmetry / allowed | grazing pairs | "
      "grazing reference asymmetry | verdict |\n|---|---|---|---|---|---|---|---|\n";
  for (const ReciprocityResult& x : r.reciprocity)
    s += fmt("| `%s` | %llu | %.1e | %.1e | %.3f | %llu | %.1e | %s |\n", x.lobe->name.c_str(),
             (unsigned long long)x.pairs, x.gpuAsymmetry, x.referenceAsymmetry, x.maxBoundRatio,
             (unsigned long long)x.grazingPairs, x.grazingReferenceAsymmetry, x.verdict().c_str());
  return s;
}

uint64_t nodesPerCell(const EnergyReport& r) {
  uint64_t cells = r.grid.NoV.size() * r.grid.perceptualRoughness.size();
  return r.furnace.empty() || cells == 0 ? 0 : r.furnace.front().nodes / cells;
}

}  // namespace

nlohmann::json energyJson(const EnergyReport& r) {
  nlohmann::json j;
  j["device"] = r.device;
  j["seconds"] = r.seconds;
  j["grid"] = {{"NoV", r.grid.NoV},
               {"perceptual_roughness", r.grid.perceptualRoughness},
               {"theta_panels", r.grid.resolution.thetaPanels},
               {"phi_panels", r.grid.resolution.phiPanels},
               {"reciprocity_pairs", r.grid.reciprocityPairs}};
  for (const LobeAlbedo& a : r.furnace) {
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& c : a.cells)
      cells.push_back({{"NoV", c.NoV},
                       {"perceptual_roughness", c.perceptualRoughness},
                       {"gpu", c.gpu},
                       {"reference", c.reference},
                       {"bound", c.bound},
                       {"convergence", c.convergence}});
    j["furnace"].push_back({{"lobe", a.lobe->name},
                            {"kind", lobeKindName(a.lobe->kind)},
                            {"map", mapName(a.lobe->map)},
                            {"theory", expectationName(a.lobe->expectation)},
                            {"note", a.lobe->note},
                            {"nodes", a.nodes},
                            {"nodes_outside_brick_tolerance", a.outsideTolerance},
                            {"max_albedo", a.maxCell().gpu},
                            {"max_mismatch_over_bound", a.maxMismatchRatio()},
                            {"max_convergence", a.maxConvergence()},
                            {"exceeds_one", a.exceedsOne()},
                            {"gpu_matches_reference", a.gpuMatchesReference()},
                            {"cells", cells}});
  }
  nlohmann::json comp = nlohmann::json::array();
  for (const auto& c : r.compensation.cells)
    comp.push_back({{"NoV", c.NoV},
                    {"perceptual_roughness", c.perceptualRoughness},
                    {"albedo", c.albedo},
                    {"dfg_y", c.dfgY},
                    {"compensation", c.compensation},
                    {"compensated", c.compensated},
                    {"margin", c.margin},
                    {"reference_minus_dfg", c.referenceVsDfg}});
  j["multiscatter"] = {{"max_deviation", r.compensation.maxDeviation()},
                       {"max_margin", r.compensation.maxMargin()},
                       {"passed", r.compensation.passed()},
                       {"cells", comp}};
  for (const ReciprocityResult& x : r.reciprocity)
    j["reciprocity"].push_back({{"lobe", x.lobe->name},
                                {"pairs", x.pairs},
                                {"gpu_asymmetry", x.gpuAsymmetry},
                                {"reference_asymmetry", x.referenceAsymmetry},
                                {"max_asymmetry_over_allowed", x.maxBoundRatio},
                                {"grazing_pairs", x.grazingPairs},
                                {"grazing_gpu_asymmetry", x.grazingGpuAsymmetry},
                                {"grazing_reference_asymmetry", x.grazingReferenceAsymmetry},
                                {"verdict", x.verdict()},
                                {"passed", x.passed()}});
  j["failures"] = r.failures();
  j["passed"] = r.failures().empty();
  return j;
}

std::string energyText(const EnergyReport& r) {
  std::string s = fmt("white furnace on %s (%zu x %zu grid, %llu nodes per cell)\n", r.device.c_str(),
                      r.grid.NoV.size(), r.grid.perceptualRoughness.size(), (unsigned long long)nodesPerCell(r));
  s += fmt("  %-46s %-14s %10s %10s %9s %9s  %s\n", "lobe", "theory", "max", "min", "err/bound", "quadr.", "verdict");
  for (const LobeAlbedo& a : r.furnace)
    s +=
        fmt("  %-46s %-14s %10.6f %10.6f %9.3f %9.1e  %s\n", a.lobe->name.c_str(), expectationName(a.lobe->expectation),
            a.maxCell().gpu, minAlbedo(a), a.maxMismatchRatio(), a.maxConvergence(), furnaceVerdict(a).c_str());
  s += fmt("multiscatter compensation (GGX, f0 = 1): max |1 - albedo| = %.2e (derived margin up to %.2e)\n",
           r.compensation.maxDeviation(), r.compensation.maxMargin());
  s += "reciprocity\n";
  for (const ReciprocityResult& x : r.reciprocity)
    s += fmt("  %-46s gpu %.1e ref %.1e err/allowed %.3f grazing ref %.1e  %s\n", x.lobe->name.c_str(), x.gpuAsymmetry,
             x.referenceAsymmetry, x.maxBoundRatio, x.grazingReferenceAsymmetry, x.verdict().c_str());
  for (const auto& f : r.failures()) s += "FAIL: " + f + "\n";
  return s;
}

std::string energyMarkdown(const EnergyReport& r, const std::string& command) {
  const EnergyGrid& g = r.grid;
  std::string s = "# Energy and reciprocity checks\n\n";
  s += "Generated by `" + command + "` on " + r.device + "; do not edit. Method: `compiler/energy/` (headers).\n\n";
  s +=
      "**Method.** The directional albedo A(v) = ∫ f(v,l) (n·l) dl of each lobe (F = 1) is integrated over half "
      "vectors (dl = 4 (v·h) dh), with θh mapped through the CDF of the lobe's own D (GGX, Beckmann, Charlie, "
      "Ashikhmin; cosine for diffuse) and the horizon n·l = 0 placed exactly (full azimuth while "
      "θh ≤ (π/2 − θv)/2, trapezoid in φ; partial azimuth [−φmax, φmax] up to (π/2 + θv)/2, Gauss-Legendre "
      "in φ), with 8-node Gauss-Legendre panels in u between breakpoints uniform in u, in θh and in φmax, and a "
      "u = u0 + (u1 − u0) t² substitution where φmax has its square-root ends (albedo_quadrature.hpp). Each brick runs as its own probe on the GPU at every node; a lobe's "
      "D·V is multiplied on the CPU from the fp32 GPU outputs (one fp32 rounding away from an in-shader "
      "product). The same nodes are integrated with the double references (at the same fp32 inputs). "
      "**Bound**: each node value lies within its brick's validated tolerance (manifest abs + rel·|ref| + input "
      "conditioning), which bounds the product by telescoping and the integral by the weighted sum; `max "
      "|GPU - ref| / bound` must be ≤ 1. **Quadrature error**: |A(N) − A(N/2)| with the references at half the "
      "resolution in θh and φ (the doubling N/2 → N); a lobe *exceeds 1* when A_GPU − 1 > bound + 2·|A(N) − A(N/2)| somewhere.\n\n";
  s +=
      fmt("Grid: n.v ∈ {%s}; perceptual roughness r ∈ {%s}, α = r² (anisotropic lobes: αt = 1.5α, αb = 0.5α, "
          "tangent 30° from the view azimuth); %d + %d θ-panels × 8 nodes, 8 × %d φ nodes: %llu nodes per cell.\n\n",
          gridLine(g.NoV).c_str(), gridLine(g.perceptualRoughness).c_str(), g.resolution.thetaPanels,
          g.resolution.thetaPanels, g.resolution.phiPanels, (unsigned long long)nodesPerCell(r));
  s += "## White furnace: specular and sheen lobes\n\n" + furnaceTable(r, false);
  s += "\n## Diffuse albedo\n\n" + furnaceTable(r, true);

  s += "\n## Lobes above 1\n\n";
  bool any = false;
  for (const LobeAlbedo& a : r.furnace) {
    if (!a.exceedsOne()) continue;
    any = true;
    const AlbedoCell& m = a.maxCell();
    s += fmt("- `%s`: %.6f at n.v = %g, r = %g (margin %.4f). ", a.lobe->name.c_str(), m.gpu, m.NoV,
             m.perceptualRoughness, m.gpu - 1.0) +
         "Why: " + a.lobe->note + ".\n";
  }
  if (!any) s += "None.\n";

  for (const LobeAlbedo& a : r.furnace) {
    if (a.lobe != r.dfgLobe) continue;
    s += "\n## GGX single-scattering albedo E(n.v, r) (`" + a.lobe->name + "`, GPU)\n\n";
    s += gridTable(g, "E", [&](size_t c) { return fmt("%.5f", a.cells[c].gpu); });
  }
  if (!r.compensation.cells.empty()) {
    s +=
        fmt("\n## Multiscatter compensation\n\n`%s` at f0 = 1 times "
            "`%s` (GPU) fed with DFG channel 1 from the CPU quadrature "
            "(`dfgIntegrals`). Max |1 − albedo| = %.2e; the derived per-cell margin (multiscatter.hpp) is at most "
            "%.2e; %s. Compensated albedo:\n\n",
            r.dfgLobe->name.c_str(), r.compensation.brick.c_str(), r.compensation.maxDeviation(),
            r.compensation.maxMargin(),
            r.compensation.passed() ? "every cell is within its margin" : "SOME CELLS ARE OUTSIDE THEIR MARGIN");
    s += gridTable(g, "E·comp", [&](size_t c) { return fmt("%.6f", r.compensation.cells[c].compensated); });
    double worst = 0;
    for (const auto& c : r.compensation.cells) worst = std::max(worst, std::abs(c.referenceVsDfg));
    s +=
        fmt("\nCross-check of the two CPU quadratures of E (this furnace's, and the DFG reference's): max "
            "|A_ref − E_dfg| = %.1e.\n",
            worst);
  }
  s += "\n## Reciprocity\n\n";
  s +=
      fmt("%u random pairs (v, l) and their swaps, on the GPU; three in four interior (n.v, n.l ∈ [1e-3, 1]), one "
          "in four grazing (one cosine in [1e-6, 1e-4], below MB_MIN_N_DOT_V). Asymmetry is |f(v,l) − f(l,v)| / "
          "max(|f|); *allowed* is the sum of both evaluations' derived bounds. The shading geometry clamps n.v to "
          "1e-4 but n.l only to 0 (common.glsl), so lobes that depend on both are not reciprocal below 1e-4.\n\n",
          g.reciprocityPairs);
  s += reciprocityTable(r);
  s += "\n## Notes per lobe\n\n";
  for (const Lobe& l : r.lobes)
    s += "- `" + l.name + "` (" + lobeKindName(l.kind) + ", " + expectationName(l.expectation) + ", quadrature map " +
         mapName(l.map) + "): " + l.note + ".\n";
  auto fails = r.failures();
  s += "\n## Result\n\n";
  if (fails.empty()) s += "All checks passed.\n";
  for (const auto& f : fails) s += "- FAIL: " + f + "\n";
  return s;
}

}  // namespace mb::energy
