// The precision axis of emitted code (DESIGN.md "permutation ... × precision"). Fp16 emits
// half arithmetic (run as the worst conforming device computes it by default, Fp16Mode): the library sources are rewritten to float16_t/f16vecN
// (fp16_rewrite.hpp), GL_EXT_shader_explicit_arithmetic_types_float16 is enabled and MB_FP16
// is defined so that a brick can add a Filament-style guard inside `#ifdef MB_FP16`. The
// probe's buffers stay fp32; values are converted at the boundary.
#pragma once
#include <optional>
#include <string>

#include "core/precision.hpp"
#include "library/shader_library.hpp"

namespace mb {

// Fp16Mediump is the fp16 axis value written for targets without 16-bit types (ESSL 3.10):
// fp32 types under `precision mediump float;` (SPIR-V RelaxedPrecision), with MB_FP16's
// guards and the fp16 roughness floor. Only the emitter produces it; a permutation's
// precision is Precision::Fp32 or Precision::Fp16 (core/precision.hpp).
enum class ShaderPrecision { Fp32, Fp16, Fp16Mediump };
// What a permutation's precision emits before the target asks for mediump.
inline ShaderPrecision shaderPrecision(Precision p) {
  return p == Precision::Fp16 ? ShaderPrecision::Fp16 : ShaderPrecision::Fp32;
}

// Fp16 or Fp16Mediump: the half-precision guards, clamps and domains apply.
inline bool isHalf(ShaderPrecision p) { return p != ShaderPrecision::Fp32; }

const char* precisionName(ShaderPrecision p);  // "fp32", "fp16"

// How validate, stress and eval run an fp16 kernel (docs/fp16.md). Emulated (the default):
// as the least precise conforming Vulkan device may compute it, whatever the driver does
// (compile/fp16_emulation.hpp: half rounding of every result, denormals flushed, division
// by the reciprocal, transcendentals at the edge of their error bounds), in fp32, so it runs
// without shaderFloat16. Driver: the device's own half arithmetic (needs shaderFloat16).
enum class Fp16Mode { Emulated, Driver };
const char* fp16ModeName(Fp16Mode m);  // "emulated", "driver"
std::optional<Fp16Mode> parseFp16Mode(const std::string& name);

// Minimum perceptual roughness per precision (Filament, "Physically Based Rendering in
// Filament" sec. 4.8.3.3, MIN_PERCEPTUAL_ROUGHNESS: 0.045 with fp32, 0.089 on mobile/fp16;
// seed 000 "Specular Miscs"). alpha = r^2, so the alpha floors are 0.002025 and 0.007921:
// 0.089^4 = 6.3e-5 keeps alpha^2 above fp16's smallest normal (6.1e-5).
inline constexpr double kMinPerceptualRoughnessFp32 = 0.045;
inline constexpr double kMinPerceptualRoughnessFp16 = 0.089;
double minPerceptualRoughness(ShaderPrecision p);
double minAlpha(ShaderPrecision p);

// The brick a material's choice maps to at this precision: at fp16 a brick's manifest
// "fp16_twin" replaces it (the Filament clamp moves to its fp16 floor, roughness_clamped ->
// roughness_clamped_fp16, as Filament's MIN_PERCEPTUAL_ROUGHNESS does); every other brick
// is kept.
std::string brickForPrecision(const ShaderLibrary& lib, const std::string& brickId, ShaderPrecision p);

}  // namespace mb
