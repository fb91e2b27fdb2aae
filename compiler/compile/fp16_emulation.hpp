// fp16 as the least precise conforming Vulkan device computes it: a SPIR-V pass over a
// kernel written with 16-bit floats (emit/precision.hpp, ShaderPrecision::Fp16) that makes it
// compute every half operation in fp32 and then round it the way the Vulkan spec's worst
// case allows, whatever the driver's own half arithmetic does (docs/fp16.md).
//
// Vulkan spec, Appendix A "Vulkan Environment for SPIR-V", "Precision and Operation of
// SPIR-V Instructions" (half-precision column):
//  - 16-bit float types, constants, vectors and matrices are retyped to 32-bit; after every
//    arithmetic result (OpFAdd, OpFSub, OpFMul, OpVectorTimesScalar, conversions, the
//    correctly rounded GLSL.std.450 instructions, ...) the value is rounded to half with
//    OpQuantizeToF16 (correctly rounded; overflow gives +-Inf);
//  - denormals: "any denormalized value ... may be flushed to zero" unless the entry point
//    declares DenormPreserve (ours do not), and devices differ (an NVIDIA H100 keeps half
//    denormals). Neither choice is the worst everywhere: flushing turns x*y into 0 where a
//    kept denormal stays finite, while a kept denormal passes a `y == 0` guard and then
//    overflows a reciprocal. The pass therefore writes either kernel (Denormals::Flush:
//    |x| < 2^-14 becomes a zero of the same sign; Denormals::Keep: rounded to the half
//    denormal grid, 2^-24) and callers run both (validate/probe_program.hpp);
//  - OpFDiv(x, y) has a defined precision only for |y| in [2^-14, 2^14]; it is evaluated as
//    x * (1/y) with the reciprocal rounded to half first, as hardware that divides by a
//    reciprocal does. Inside the range that is within the spec's 2.5 ULP; outside, 1/y of a
//    huge y is a denormal (or 0), of a denormal y is Inf (1/2^-16 > 65504) and of 0 is Inf,
//    so 0 * Inf = NaN shows;
//  - operations the spec defines as "inherited from" a formula are expanded into that
//    formula, each step rounded: OpDot (sum of products), length, distance, normalize,
//    cross, reflect, faceforward, mix, fma, smoothstep, pow = exp2(y log2 x),
//    sqrt = 1 / inversesqrt, tan = sin / cos, asin/acos through atan2, OpFMod/OpFRem, and
//    the matrix products;
//  - results with an error bound are moved to the edge of that bound, in a direction taken
//    from a hash of the operands' bits (deterministic, both directions occur): exp, exp2
//    (1 + 2|x| ULP), log, log2 (3 ULP, or absolute 2^-7 inside [0.5, 2]), inversesqrt
//    (2 ULP), sin, cos (absolute 2^-7), atan, atan2 (5 ULP). The ULP is the half spacing
//    of the result's own binade, so a result that underflows stays an underflow (the
//    literal ulp(0) of a flushing device, 2^-14, would let exp(-1000) return 0.12).
// The kernel's buffer boundary stays as it was: its fp32 loads convert to half with a
// rounding (OpFConvert -> quantize and flush), and its stores convert back exactly.
// What this cannot model (docs/fp16.md): contraction into fused multiply-add or other
// reassociation a driver may do, the driver's own rounding mode (round-to-nearest here),
// optimizations that assume no NaN/Inf, and RelaxedPrecision.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

// Rewrites a valid SPIR-V module whose arithmetic uses 16-bit floats (and no 16-bit float
// storage) into one that emulates the worst conforming half arithmetic in 32-bit floats,
// validated with spirv-val (Vulkan 1.1 rules, as compileComputeGlsl). The result declares no Float16 capability, so it runs without shaderFloat16. Throws
// DiagnosticError E-FP16-EMULATION (naming `displayName`) for an instruction it cannot
// emulate faithfully (a bitcast of a half, a matrix inverse, ...).
enum class Denormals { Flush, Keep };
std::vector<uint32_t> emulateWorstCaseFp16(const std::vector<uint32_t>& spirv, const std::string& displayName,
                                           Denormals denormals);

// Counts of what the pass did, for tests: how many results were rounded, divisions
// rewritten, inherited formulas expanded and bounded results perturbed.
struct Fp16EmulationStats {
  uint32_t rounded = 0;
  uint32_t divisions = 0;
  uint32_t expanded = 0;
  uint32_t perturbed = 0;
};
std::vector<uint32_t> emulateWorstCaseFp16(const std::vector<uint32_t>& spirv, const std::string& displayName,
                                           Denormals denormals, Fp16EmulationStats& stats);

}  // namespace mb
