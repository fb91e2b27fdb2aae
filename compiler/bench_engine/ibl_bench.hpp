// The IBL table: DFG LUTs of several sizes at fp16 and fp32 (bench_engine/dfg_lut.hpp), their
// error against the integrated split-sum on the same samples as the env_brdf bricks, so that
// LUTs and the analytic env-BRDF bricks read against one yardstick.
#pragma once
#include <ostream>

#include "bench_engine/bench_runner.hpp"

namespace mb::bench {

// Fills `out` and returns true; false (nothing measured) when the library has no env_brdf
// slot with the inputs f0, perceptualRoughness, NoV to take samples from.
bool measureDfgLuts(const ShaderLibrary& lib, const BenchOptions& options, IblSection& out, ProgressSink* progress);

}  // namespace mb::bench
