#include <sstream>

#include "bench_engine/cost_format.hpp"
#include "bench_engine/report.hpp"

namespace mb::bench {
namespace {

std::string g(double v) { return printfDouble("%.6g", v); }

// Cost columns: a cost below resolution has no value, only the bound it is below; the
// interval is only given where it separates the cost from the empty loop.
std::string costColumns(const CostMeasurement& c) {
  return (c.resolved ? g(c.nsPerEval) + "," + g(c.nsPerEvalLow) + "," + g(c.nsPerEvalHigh) + "," : std::string(",,,")) +
         (c.resolved ? std::string("") : g(c.nsUpperBound())) + "," + g(c.confidence) + "," + g(c.nsRaw) + "," +
         g(c.nsBaseline) + "," + std::to_string(c.iterations) + "," + std::to_string(c.records);
}

std::string errorColumns(const ErrorSummary& e) {
  return g(e.maxScaled()) + "," + g(e.meanScaled()) + "," + g(e.maxAbs()) + "," + g(e.meanAbs()) + "," + g(e.maxRel()) +
         "," + g(e.meanRel()) + "," + std::to_string(e.nonFinite());
}

}  // namespace

std::string toCsv(const BenchReport& r) {
  std::ostringstream s;
  s << "group,id,kind,ns_per_eval,ns_per_eval_ci_low,ns_per_eval_ci_high,ns_per_eval_below,ci_confidence,"
       "ns_per_eval_raw,ns_per_eval_loop_baseline,iterations_per_record,records_per_dispatch,static_cost_fma,"
       "spirv_instructions,lut_bytes,yardstick,max_error,mean_error,max_abs,mean_abs,max_rel,mean_rel,non_finite,"
       "on_frontier,tied_with\n";
  for (const auto& grp : r.groups)
    for (const auto& it : grp.items)
      s << grp.name << "," << it.id << "," << it.kind << "," << costColumns(it.cost) << "," << g(it.staticCost) << ","
        << it.spirvInstructions << ",," << it.yardstick << "," << errorColumns(it.error) << ","
        << (it.onFrontier ? 1 : 0) << "," << it.tiedWith << "\n";
  if (r.hasIbl)
    for (const auto& l : r.ibl.luts)
      s << "ibl,dfg_lut_" << l.size << "_" << lut::lutFormatName(l.format) << ",lut,,,,,,,,,,,," << l.bytes
        << ",ground_truth," << errorColumns(l.error) << ",,\n";
  return s.str();
}

}  // namespace mb::bench
