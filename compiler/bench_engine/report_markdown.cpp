#include <algorithm>
#include <cstdio>
#include <sstream>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/report.hpp"

namespace mb::bench {
namespace {

std::string g3(double v) { return printfDouble("%.3g", v); }
std::string staticText(double v) { return printfDouble("%.1f", v); }

std::string frontierText(const BenchItem& it) {
  if (it.onFrontier) return "yes";
  return it.tiedWith.empty() ? "" : "tie with `" + it.tiedWith + "`";
}

std::string yardstickText(const BenchItem& it) {
  if (it.yardstick == "reference") return "own reference (no ground truth)";
  if (it.kind == "brick") return "ground truth";
  std::string s = "ground truth of";
  for (size_t i = 0; i < it.groundTruthBricks.size(); ++i) s += (i ? ", `" : " `") + it.groundTruthBricks[i] + "`";
  return s;
}

void writeGroup(std::ostringstream& s, const BenchGroup& grp) {
  s << "### `" << grp.name << "`\n\n"
    << "| " << (grp.name == "materials" ? "permutation" : "brick")
    << " | cost / eval (95 % interval) | static cost (FMA) | SPIR-V instructions | max error | mean error | "
       "measured against | frontier |\n"
    << "|---|---:|---:|---:|---:|---:|---|:-:|\n";
  for (const auto& it : grp.items)
    s << "| `" << it.id << "` | " << formatCostWithInterval(it.cost) << " | " << staticText(it.staticCost) << " | "
      << it.spirvInstructions << " | " << g3(it.error.maxScaled()) << " | " << g3(it.error.meanScaled()) << " | "
      << yardstickText(it) << " | " << frontierText(it) << " |\n";
  std::vector<const BenchItem*> front;
  for (const auto& it : grp.items)
    if (it.onFrontier) front.push_back(&it);
  // Frontier order: by cost; below-resolution items (bounded only) first.
  auto key = [](const BenchItem* it) { return it->cost.resolved ? it->cost.nsPerEval : 0.0; };
  std::stable_sort(front.begin(), front.end(), [&](auto* a, auto* b) { return key(a) < key(b); });
  if (front.empty()) return void(s << "\n");
  auto point = [](const BenchItem& it) {
    return formatCost(it.cost) + ", static " + staticText(it.staticCost) + ", max error " + g3(it.error.maxScaled());
  };
  s << "\nFrontier, cheapest first (a step between equally accurate points may be within the noise; a less accurate point is on it only where significantly cheaper): `"
    << front[0]->id << "` (" << point(*front[0]) << ")";
  for (size_t k = 1; k < front.size(); ++k) {
    const BenchItem &a = *front[k - 1], &b = *front[k];
    double ratio = b.error.maxScaled() > 0 ? a.error.maxScaled() / b.error.maxScaled() : 0;
    s << "; then `" << b.id << "` (" << point(b) << ")" << (ratio > 0 ? ": " + g3(ratio) + "x smaller error" : "");
  }
  s << ".\n\n";
}

void writeIbl(std::ostringstream& s, const BenchReport& r) {
  s << "### IBL: DFG LUT or analytic env-BRDF\n\n"
    << "Against the integrated split sum `f0 ∫Gv + (1 − f0) ∫Gv·Fc` (GGX, exact correlated Smith), on the "
    << r.ibl.samples << " samples of `" << r.ibl.samplesFrom
    << "` (every channel of f0). LUTs: RG texels at centres (i + 0.5)/size, u = n·v, v = perceptual "
       "roughness, bilinear with clamp-to-edge emulated on the CPU in double; their cost is memory "
       "(the harness has no texture path to time a fetch). Analytic bricks: GPU output, cost measured "
       "as above.\n\n"
    << "| choice | cost | max error | mean error |\n|---|---|---:|---:|\n";
  for (const auto& grp : r.groups)
    if (grp.name == "env_brdf")
      for (const auto& it : grp.items)
        s << "| `" << it.id << "` (analytic" << (it.truthNote.empty() ? "" : ", " + it.truthNote) << ") | "
          << formatCost(it.cost) << " / eval, static " << staticText(it.staticCost) << " | " << g3(it.error.maxScaled())
          << " | " << g3(it.error.meanScaled()) << " |\n";
  for (const auto& l : r.ibl.luts)
    s << "| DFG LUT " << l.size << "×" << l.size << " " << lut::lutFormatName(l.format) << " | " << l.bytes
      << " bytes | " << g3(l.error.maxScaled()) << " | " << g3(l.error.meanScaled()) << " |\n";
  s << "\n";
}

}  // namespace

std::string printfDouble(const char* format, double value) {
  char b[64];
  std::snprintf(b, sizeof b, format, value);
  return b;
}

std::string describeRun(const BenchReport& r) {
  const BenchOptions& o = r.options;
  const std::string iterations = o.cost.iterations ? std::to_string(o.cost.iterations) + " evaluations per record"
                                                   : "evaluations per record calibrated";
  return "device " + r.device + "; medians of " + std::to_string(o.cost.repeats) +
         " paired repeats with 95 % intervals, " + iterations + "; " + std::to_string(o.samples) +
         " error samples (seed " + std::to_string(o.seed) + ")";
}

std::string toMarkdown(const BenchReport& r) {
  std::ostringstream s;
  s << "Measured with " << describeRun(r) << ". Errors: max and mean over the samples of "
    << "|x − truth| / max(1, |truth|). Cost: the bench kernel's time net of the empty loop per evaluation, median "
    << "and distribution-free 95 % interval of the paired repeats, or \"below resolution\" where the interval does "
    << "not clear the timer's resolution. Static cost: one iteration of the timed loop less its counter (the call, "
    << "the perturbation of the inputs it reads, the add of its result) weighted by throughput, in fp32 FMA issue "
    << "slots (CUDA C++ Programming Guide, compute capability 9.0). A frontier step needs a significantly "
    << "higher cost (disjoint intervals); a point that is cheaper only within the noise is a tie.\n\n";
  for (const auto& grp : r.groups) writeGroup(s, grp);
  if (r.hasIbl) writeIbl(s, r);
  return s.str();
}

std::string spliceGenerated(const std::string& document, const std::string& generated) {
  const std::string begin = kMarkdownBegin, end = kMarkdownEnd;
  size_t b = document.find(begin), e = document.find(end);
  std::string body = begin + "\n" + generated + end;
  if (b == std::string::npos || e == std::string::npos || e < b) return body + "\n";
  return document.substr(0, b) + body + document.substr(e + end.size());
}

}  // namespace mb::bench
