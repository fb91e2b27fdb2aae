// A hand-written SVG Pareto chart for one bench group: cost (ns per evaluation) on a linear x
// axis, max error on a log y axis, every item a labelled point, the frontier drawn as a line
// through its non-dominated points. Plain text, no dependency.
#pragma once
#include <string>

#include "bench_engine/bench_runner.hpp"

namespace mb::bench {

// `subtitle` names the machine/device the costs were measured on.
std::string paretoSvg(const BenchGroup& group, const std::string& subtitle);

// Grid step for a linear axis: 1, 2 or 5 times a power of ten, about range/5 (also the
// report's albedo charts, report/albedo_chart.hpp).
double niceStep(double range);

// Text safe inside an XML element or attribute.
std::string xmlEscape(const std::string& s);

}  // namespace mb::bench
