// compile: HLSL to SPIR-V through glslang's HLSL front end, keeping the module that the hlsl
// target's check (target_checks.hpp) makes and validates, so that the HLSL can be run
// (validate --target hlsl; docs/targets.md "Executed"). DXC is not packaged in Debian.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

// checkHlsl's reparse (entry point "main", Vulkan 1.1, spirv-val), keeping glslang's SPIR-V:
// "" and the module in `spirv`, else the first message. `samplerShift`: each s register's
// binding is its number plus this (glslang's setShiftBinding; DXC's -fvk-s-shift), so that a
// texture t<n> and its sampler s<n> do not share binding n, which Vulkan does not allow.
std::string compileHlsl(const std::string& source, std::vector<uint32_t>& spirv, bool fragment = false,
                        unsigned samplerShift = 0);

// The binding shift the preview gives samplers (preview/draw_passes.cpp): above every binding of
// the fragment interface (docs/fragment-stage.md).
inline constexpr unsigned kHlslSamplerShift = 16;

// SPIRV-Cross's HLSL fragment shader, with [[vk::location(n)]] on each input of its
// SPIRV_Cross_Input struct that carries semantic TEXCOORD<n>. glslang numbers HLSL inputs in
// declaration order, so a shader that reads TEXCOORD0, 1 and 3 would take its uv from the vertex
// stage's location 2 (measured with glslang 12). An engine that compiles this HLSL for Vulkan
// against the reference vertex shader needs the locations, as the preview does. Unchanged when
// there is no such struct.
std::string hlslWithInputLocations(const std::string& hlsl);

}  // namespace mb
