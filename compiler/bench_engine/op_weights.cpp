#include "bench_engine/op_weights.hpp"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/GLSL.std.450.h>
#include <spirv/unified1/spirv.hpp>

namespace mb::bench {
namespace {

// CUDA C++ Programming Guide, "Throughput of Native Arithmetic Instructions", compute
// capability 9.0, as 128 / (results per clock per multiprocessor).
constexpr double kFp32 = 1;        // add, multiply, multiply-add: 128
constexpr double kSpecial = 8;     // reciprocal, rsqrt, log2, exp2, sine, cosine: 16
constexpr double kInteger = 2;     // integer add/multiply, compare, min, max, shift, bitwise: 64
constexpr double kConversion = 8;  // type conversions: 16
// "Integer division and modulo operation ... compile to up to 20 instructions" (same guide,
// "Integer Arithmetic").
constexpr double kIntegerDivision = 20 * kInteger;
// Composite lowerings the guide describes: division = reciprocal + multiply (Vulkan allows
// 2.5 ULP, which that meets); square root = reciprocal square root + reciprocal.
constexpr double kDivision = kSpecial + kFp32;
constexpr double kSqrt = 2 * kSpecial;

}  // namespace

double coreOpWeight(uint32_t opcode, uint32_t operandComponents) {
  switch (static_cast<spv::Op>(opcode)) {
    case spv::OpFAdd:
    case spv::OpFSub:
    case spv::OpFMul:
    case spv::OpFNegate:
    case spv::OpVectorTimesScalar:
      return kFp32;
    case spv::OpDot:
      return kFp32 * operandComponents;
    case spv::OpFDiv:
      return kDivision;
    case spv::OpFRem:
    case spv::OpFMod:
      return kDivision + kConversion + kFp32;  // x - y * trunc(x / y)
    case spv::OpIAdd:
    case spv::OpISub:
    case spv::OpIMul:
    case spv::OpSNegate:
    case spv::OpShiftLeftLogical:
    case spv::OpShiftRightLogical:
    case spv::OpShiftRightArithmetic:
    case spv::OpBitwiseAnd:
    case spv::OpBitwiseOr:
    case spv::OpBitwiseXor:
    case spv::OpNot:
    case spv::OpBitFieldInsert:
    case spv::OpBitFieldSExtract:
    case spv::OpBitFieldUExtract:
    case spv::OpBitReverse:
    case spv::OpBitCount:
      return kInteger;
    case spv::OpUDiv:
    case spv::OpSDiv:
    case spv::OpUMod:
    case spv::OpSRem:
    case spv::OpSMod:
      return kIntegerDivision;
    case spv::OpFOrdEqual:
    case spv::OpFUnordEqual:
    case spv::OpFOrdNotEqual:
    case spv::OpFUnordNotEqual:
    case spv::OpFOrdLessThan:
    case spv::OpFUnordLessThan:
    case spv::OpFOrdGreaterThan:
    case spv::OpFUnordGreaterThan:
    case spv::OpFOrdLessThanEqual:
    case spv::OpFUnordLessThanEqual:
    case spv::OpFOrdGreaterThanEqual:
    case spv::OpFUnordGreaterThanEqual:
    case spv::OpIEqual:
    case spv::OpINotEqual:
    case spv::OpUGreaterThan:
    case spv::OpSGreaterThan:
    case spv::OpUGreaterThanEqual:
    case spv::OpSGreaterThanEqual:
    case spv::OpULessThan:
    case spv::OpSLessThan:
    case spv::OpULessThanEqual:
    case spv::OpSLessThanEqual:
    case spv::OpIsNan:
    case spv::OpIsInf:
    case spv::OpSelect:
    case spv::OpLogicalEqual:
    case spv::OpLogicalNotEqual:
    case spv::OpLogicalOr:
    case spv::OpLogicalAnd:
    case spv::OpLogicalNot:
      return kInteger;
    case spv::OpAny:
    case spv::OpAll:
      return kInteger * operandComponents;
    case spv::OpConvertFToU:
    case spv::OpConvertFToS:
    case spv::OpConvertSToF:
    case spv::OpConvertUToF:
    case spv::OpUConvert:
    case spv::OpSConvert:
    case spv::OpFConvert:
    case spv::OpQuantizeToF16:
      return kConversion;
    default:
      return 0;  // data movement, control flow, declarations
  }
}

double glslStd450Weight(uint32_t instruction, uint32_t n, bool& perComponent) {
  perComponent = true;
  switch (static_cast<GLSLstd450>(instruction)) {
    case GLSLstd450FAbs:
    case GLSLstd450Radians:
    case GLSLstd450Degrees:
    case GLSLstd450Fma:
      return kFp32;
    case GLSLstd450SAbs:
    case GLSLstd450FMin:
    case GLSLstd450UMin:
    case GLSLstd450SMin:
    case GLSLstd450FMax:
    case GLSLstd450UMax:
    case GLSLstd450SMax:
    case GLSLstd450NMin:
    case GLSLstd450NMax:
    case GLSLstd450Ldexp:
    case GLSLstd450Frexp:
    case GLSLstd450FrexpStruct:
    case GLSLstd450FindILsb:
    case GLSLstd450FindSMsb:
    case GLSLstd450FindUMsb:
      return kInteger;
    case GLSLstd450FClamp:
    case GLSLstd450UClamp:
    case GLSLstd450SClamp:
    case GLSLstd450NClamp:
    case GLSLstd450FSign:
    case GLSLstd450SSign:
    case GLSLstd450Step:
      return 2 * kInteger;  // min + max; two compares + select
    case GLSLstd450FMix:
      return 2 * kFp32;  // x + a (y - x)
    case GLSLstd450Round:
    case GLSLstd450RoundEven:
    case GLSLstd450Trunc:
    case GLSLstd450Floor:
    case GLSLstd450Ceil:
      return kConversion;  // our estimate: rounding to an integral value as a conversion
    case GLSLstd450Fract:
    case GLSLstd450Modf:
    case GLSLstd450ModfStruct:
      return kConversion + kFp32;  // x - floor(x)
    case GLSLstd450Exp2:
    case GLSLstd450Log2:
    case GLSLstd450InverseSqrt:
      return kSpecial;
    case GLSLstd450Exp:
    case GLSLstd450Log:
    case GLSLstd450Sin:
    case GLSLstd450Cos:
      return kSpecial + kFp32;  // a scale by log2(e), ln 2 or 1/2pi, then the special op
    case GLSLstd450Sqrt:
      return kSqrt;
    case GLSLstd450Pow:
      return 2 * kSpecial + kFp32;  // exp2(y log2 x)
    case GLSLstd450Tan:
      return 2 * (kSpecial + kFp32) + kDivision;
    case GLSLstd450Atan:
      return kDivision + 8 * kFp32;  // our estimate: range reduction + a degree-8 polynomial
    case GLSLstd450Atan2:
      return 2 * kDivision + 8 * kFp32 + 2 * kInteger;
    case GLSLstd450Asin:
    case GLSLstd450Acos:
      return kSqrt + 8 * kFp32;  // our estimate: sqrt(1 - x) times a polynomial
    case GLSLstd450Sinh:
    case GLSLstd450Cosh:
    case GLSLstd450Tanh:
      return 2 * (kSpecial + kFp32) + kDivision;
    case GLSLstd450Asinh:
    case GLSLstd450Acosh:
    case GLSLstd450Atanh:
      return kSqrt + kSpecial + 3 * kFp32;
    case GLSLstd450SmoothStep:
      return kDivision + 2 * kInteger + 3 * kFp32;  // t = clamp((x - a) / (b - a)); t^2 (3 - 2t)
    case GLSLstd450PackHalf2x16:
    case GLSLstd450UnpackHalf2x16:
    case GLSLstd450PackSnorm2x16:
    case GLSLstd450PackUnorm2x16:
    case GLSLstd450UnpackSnorm2x16:
    case GLSLstd450UnpackUnorm2x16:
    case GLSLstd450PackSnorm4x8:
    case GLSLstd450PackUnorm4x8:
    case GLSLstd450UnpackSnorm4x8:
    case GLSLstd450UnpackUnorm4x8:
      return kConversion;
    default:
      break;
  }
  perComponent = false;  // whole-operation costs over n-component operands
  switch (static_cast<GLSLstd450>(instruction)) {
    case GLSLstd450Length:
      return n * kFp32 + kSqrt;
    case GLSLstd450Distance:
      return 2 * n * kFp32 + kSqrt;
    case GLSLstd450Normalize:
      return 2 * n * kFp32 + kSpecial;  // dot, rsqrt, scale
    case GLSLstd450Cross:
      return 6 * kFp32;
    case GLSLstd450Reflect:
      return 3 * n * kFp32;  // I - 2 dot(N, I) N
    case GLSLstd450FaceForward:
      return n * kFp32 + 2 * kInteger * n;
    case GLSLstd450Refract:
      return 4 * n * kFp32 + kSqrt + 4 * kFp32;
    default:
      perComponent = true;
      return kFp32;  // anything else: one operation per component (our estimate)
  }
}

}  // namespace mb::bench
