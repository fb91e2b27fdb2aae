// The IBL table: DFG LUTs of several sizes at fp16 and fp32 (lut/dfg_lut.hpp, DfgLut), their
// error against the integrated split-sum on the same samples as the env_brdf bricks, so that
// LUTs and the analytic env-BRDF bricks read against one yardstick. The error is measured on
// the CPU; the harness binds storage buffers only, so a LUT's cost is given as its size in
// bytes, not in ns.
#pragma once
#include <ostream>

#include "bench_engine/bench_runner.hpp"

namespace mb::bench {

// Fills `out` and returns true; false (nothing measured) when the library has no env_brdf
// slot with the inputs f0, perceptualRoughness, NoV to take samples from.
bool measureDfgLuts(const ShaderLibrary& lib, const BenchOptions& options, IblSection& out, ProgressSink* progress);

}  // namespace mb::bench
