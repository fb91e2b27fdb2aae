// The input domain a probe is judged on at each precision. At fp32 it is the manifest's
// declared domain. At fp16 the roughness-like inputs start at Filament's fp16 floor
// (precision.hpp: perceptual roughness 0.089, alpha 0.089^2), because below it 1/alpha^2
// terms leave the half range (max 65504) -- Filament clamps roughness in mediump for the same
// reason (MIN_PERCEPTUAL_ROUGHNESS on mobile).
#pragma once
#include <string>

#include "emit/precision.hpp"
#include "library/shader_library.hpp"
#include "validate/sampler.hpp"

namespace mb {

// Which inputs are roughness-like is library data (ShaderLibrary::roughnessKind: a slot
// parameter's or model input's "roughness", docs/formats.md): "alpha", "at", "ab" (the
// anisotropic alphas) are linear roughness alpha; "perceptualRoughness" and "roughness" (the
// standard model's input) are perceptual.
//
// The smallest value a roughness-like input takes at this precision (0 for other inputs).
double roughnessFloor(RoughnessKind kind, ShaderPrecision p);

// `declared` with every roughness-like range raised to start at roughnessFloor (ranges
// already above it are kept; a range entirely below it is left as declared), and the
// library's roughness kinds in `roughness`.
SampleDomain domainAtPrecision(const ShaderLibrary& lib, const SampleDomain& declared, ShaderPrecision p);

}  // namespace mb
