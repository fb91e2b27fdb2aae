// Per-operation weights of bench_engine/static_cost.hpp (which documents the table they come from).
#pragma once
#include <cstdint>

namespace mb::bench {

// Weight per result component of a core SPIR-V opcode, in fp32 FMA issue slots; 0 for
// data movement and control flow. `operandComponents` is the component count of the first
// operand (OpDot, whose result is a scalar, costs one FMA per operand component).
double coreOpWeight(uint32_t opcode, uint32_t operandComponents);

// The same for a GLSL.std.450 extended instruction, per result component;
// `operandComponents` serves the ones with scalar results (Length, Distance) and the ones
// whose cost is per operand (Normalize, Reflect, Refract, FaceForward), which then return
// their whole cost as if for one component (`perComponent` set false).
double glslStd450Weight(uint32_t instruction, uint32_t operandComponents, bool& perComponent);

}  // namespace mb::bench
