#include <sstream>

#include "bench/report.hpp"

namespace mb::bench {
namespace {

std::string g(double v) { return printfDouble("%.6g", v); }

std::string errorColumns(const ErrorSummary& e) {
  return g(e.maxScaled()) + "," + g(e.meanScaled()) + "," + g(e.maxAbs()) + "," + g(e.meanAbs()) + "," + g(e.maxRel()) +
         "," + g(e.meanRel()) + "," + std::to_string(e.nonFinite());
}

}  // namespace

std::string toCsv(const BenchReport& r) {
  std::ostringstream s;
  s << "group,id,kind,ns_per_eval,ns_per_eval_from_minima,ns_per_eval_raw,ns_per_eval_loop_baseline,spirv_instructions,lut_bytes,"
       "yardstick,max_error,mean_error,max_abs,mean_abs,max_rel,mean_rel,non_finite,on_frontier\n";
  for (const auto& grp : r.groups)
    for (const auto& it : grp.items)
      s << grp.name << "," << it.id << "," << it.kind << "," << g(it.cost.nsPerEval) << "," << g(it.cost.nsPerEvalMin)
        << "," << g(it.cost.nsRaw) << "," << g(it.cost.nsBaseline) << "," << it.spirvInstructions << ",,"
        << it.yardstick << "," << errorColumns(it.error) << "," << (it.onFrontier ? 1 : 0) << "\n";
  if (r.hasIbl)
    for (const auto& l : r.ibl.luts)
      s << "ibl,dfg_lut_" << l.size << "_" << lutFormatName(l.format) << ",lut,,,,,," << l.bytes << ",ground_truth,"
        << errorColumns(l.error) << ",\n";
  return s.str();
}

}  // namespace mb::bench
