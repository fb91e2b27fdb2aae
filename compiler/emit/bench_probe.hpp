// Emit: the "bench probe", a compute kernel that times a brick or a permutation. It is the
// ordinary probe's GLSL (same includes, same record layout, same harness contract) with its
// entry point renamed away and a timing entry point appended: each invocation
// reads its record once and evaluates the call `iterations` times, scaling every input by
// (1 - k * 2^-20) in iteration k so that no call is loop-invariant (the compiler cannot
// hoist it out of the loop), and adds every result into the output (so none is dead code).
// The baseline variant runs the same loop with the call replaced by the sum of the scaled
// inputs: its time is the loop, the perturbation, the accumulation and the memory traffic,
// which bench subtracts so that what remains is the brick's own cost. A permutation's call is
// its probe's whole function (permutationRadianceCall, emitter.hpp): every light of the
// permutation and its environment, as validation evaluates it.
#pragma once
#include <cstdint>

#include "emit/emitter.hpp"

namespace mb {

struct BenchProbeOptions {
  uint32_t iterations = 64;  // evaluations per invocation (amortizes the record read/write)
  bool baseline = false;     // the empty loop instead of the call
};

EmittedShader emitBrickBenchProbe(const ShaderLibrary& lib, const Brick& brick, const BenchProbeOptions& options);
EmittedShader emitPermutationBenchProbe(const ShaderLibrary& lib, const Permutation& perm,
                                        const BenchProbeOptions& options);

}  // namespace mb
