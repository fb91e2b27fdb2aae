// A deterministic cost beside the measured one: the operations of optimized SPIR-V weighted by
// a published per-operation throughput table, so that it does not move with the machine's
// load and needs no device.
//
// Weights (op_weights.cpp) are in fp32 FMA issue slots: 128 / (results per clock per
// multiprocessor) from the table "Throughput of Native Arithmetic Instructions" of NVIDIA's
// CUDA C++ Programming Guide (section "Arithmetic Instructions"), compute capability 9.0
// (H100): fp32 add / multiply / multiply-add 128 (weight 1); fp32 reciprocal, reciprocal
// square root, base-2 logarithm, base-2 exponential, sine, cosine 16 (weight 8); 32-bit
// integer add, compare, minimum, maximum, shift, bitwise ops 64 (weight 2); type conversions
// 16 (weight 8). Operations the table does not list are weighted by the native instructions
// they lower to, as the same guide describes them (a square root is a reciprocal square root
// followed by a reciprocal; a division a reciprocal and a multiply; pow a log2, a multiply and
// an exp2); the rest are our estimates, marked as such in op_weights.cpp. Data movement
// (loads, stores, access chains, composite construct / extract, shuffles, phis, bitcasts)
// weighs 0. Each op counts once per component of its result.
//
// Along which path: the entry point's structured control flow is walked; a selection counts
// its costliest arm (the cost of an invocation that takes it; a warp whose invocations
// diverge pays more), and a loop counts its body (its costliest iteration) times its trip
// count when that is a constant the loop's induction variable reveals (OpPhi from a
// constant, a constant step, a compare against a constant), else once (counted in
// `loopsWithUnknownTripCount`). Calls count their callee the same way.
#pragma once
#include <cstdint>
#include <vector>

namespace mb::bench {

struct StaticCost {
  double fmaSlots = 0;  // weighted operations along the costliest path
  uint32_t loops = 0;
  uint32_t loopsWithUnknownTripCount = 0;
  // One iteration of the entry point's first outermost loop (its costliest path), less the
  // loop counter's increment and exit test when the trip count was read from them.
  bool outerLoopFound = false;
  double outerLoopIteration = 0;
};

// Throws std::runtime_error on a module it cannot read (not SPIR-V, no entry point).
StaticCost staticCost(const std::vector<uint32_t>& spirv);

// The bench probe's static cost per evaluation: one iteration of the timed kernel's loop, less
// its counter: the call's own operations, the perturbation of the inputs the optimized call
// still reads, and the add that accumulates its result (one per output component, so never
// 0). Deliberately not "timed minus empty loop": the empty loop perturbs and sums every
// input, while the optimizer drops the perturbation of inputs a brick ignores, so that
// difference goes negative for bricks that read few inputs. Throws when the kernel has no loop.
double staticCostPerEvaluation(const std::vector<uint32_t>& timed);

}  // namespace mb::bench
