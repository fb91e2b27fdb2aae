#include <cmath>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/report.hpp"

namespace mb::bench {
namespace {

nlohmann::json number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");  // JSON has no Inf
}

nlohmann::json toJson(const ErrorSummary& e) {
  return {{"values", e.values()},
          {"max", number(e.maxScaled())},
          {"mean", number(e.meanScaled())},
          {"max_abs", number(e.maxAbs())},
          {"mean_abs", number(e.meanAbs())},
          {"max_rel", number(e.maxRel())},
          {"mean_rel", number(e.meanRel())},
          {"non_finite", e.nonFinite()},
          {"truth_invalid", e.truthInvalid()}};
}

}  // namespace

nlohmann::json toJson(const CostMeasurement& c) {
  nlohmann::json j{{"resolved", c.resolved},
                   {"text", formatCostWithInterval(c)},
                   {"ci_confidence", c.confidence},
                   {"ns_resolution", number(c.nsResolution)},
                   {"ns_loop_baseline_spread", number(c.nsBaselineSpread)},
                   {"ns_per_eval_raw", number(c.nsRaw)},
                   {"ns_per_eval_loop_baseline", number(c.nsBaseline)},
                   {"records_per_dispatch", c.records},
                   {"iterations_per_record", c.iterations},
                   {"evaluations_per_dispatch", c.evaluations},
                   {"calibration_rounds", c.calibrationRounds},
                   {"gpu_timestamps", c.gpuTimestamps}};
  // Only a resolved cost has a value and an interval; otherwise only the bound it is below.
  if (c.resolved) {
    j["ns_per_eval"] = number(c.nsPerEval);
    j["ns_per_eval_ci"] = {number(c.nsPerEvalLow), number(c.nsPerEvalHigh)};
  } else {
    j["ns_per_eval_below"] = number(c.nsUpperBound());
  }
  return j;
}

namespace {

nlohmann::json toJson(const BenchItem& it) {
  return {{"id", it.id},
          {"kind", it.kind},
          {"ns_per_eval", it.cost.resolved ? number(it.cost.nsPerEval) : nlohmann::json(nullptr)},
          {"cost", toJson(it.cost)},
          {"static_cost_fma", number(it.staticCost)},
          {"spirv_instructions", it.spirvInstructions},
          {"yardstick", it.yardstick},
          {"ground_truth_bricks", it.groundTruthBricks},
          {"error", toJson(it.error)},
          {"fp32_vs_reference",
           {{"max_abs", number(it.vsReference.maxAbs)},
            {"max_rel", number(it.vsReference.maxRel)},
            {"nan_count", it.vsReference.nanCount},
            {"inf_count", it.vsReference.infCount},
            {"within_tolerance", it.vsReference.passed()}}},
          {"on_frontier", it.onFrontier},
          {"tied_with", it.tiedWith}};
}

}  // namespace

nlohmann::json toJson(const BenchReport& r) {
  const BenchOptions& o = r.options;
  nlohmann::json out{{"tool", "matbricks bench " MB_VERSION},
                     {"device", r.device},
                     {"toolchain", r.toolchain},
                     {"options",
                      {{"repeats", o.cost.repeats},
                       {"samples", o.samples},
                       {"seed", o.seed},
                       {"records", o.cost.records},
                       {"iterations", o.cost.iterations},
                       {"target_dispatch_ms", o.cost.targetDispatchMs},
                       {"max_dispatch_ms", o.cost.maxDispatchMs},
                       {"optimization", optimizationLevelName(o.cost.optimization)},
                       {"lut_sizes", o.lutSizes}}},
                     {"error_metric", "|x - truth| / max(1, |truth|) over every output value of every sample"},
                     {"cost_method", kCostMethod},
                     {"static_cost_method", kStaticCostMethod},
                     {"groups", nlohmann::json::array()}};
  for (const auto& g : r.groups) {
    nlohmann::json items = nlohmann::json::array(), frontier = nlohmann::json::array();
    for (const auto& it : g.items) items.push_back(toJson(it));
    for (const auto& it : g.items)
      if (it.onFrontier) frontier.push_back(it.id);
    out["groups"].push_back({{"name", g.name}, {"frontier", frontier}, {"items", items}});
  }
  if (r.hasIbl) {
    nlohmann::json luts = nlohmann::json::array();
    for (const auto& l : r.ibl.luts)
      luts.push_back(
          {{"size", l.size}, {"format", lut::lutFormatName(l.format)}, {"bytes", l.bytes}, {"error", toJson(l.error)}});
    out["ibl"] = {
        {"samples_from", r.ibl.samplesFrom},
        {"samples", r.ibl.samples},
        {"ground_truth", "split-sum integral f0 Int Gv + (1 - f0) Int Gv Fc, GGX, exact correlated Smith (quadrature)"},
        {"filtering", "bilinear, clamp-to-edge, texel centres (i + 0.5)/size, emulated on the CPU in double"},
        {"luts", luts}};
  }
  return out;
}

}  // namespace mb::bench
