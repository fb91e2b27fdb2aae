// The descriptor bindings (all in set 0) of the shaders the compiler emits, named once for
// the code that writes them (emit/), binds them (harness/, preview/) and describes them to an
// engine (write/: the manifest and the C++ header). A bottom-layer header, so that each of
// those can include it without depending on another.
#pragma once

namespace mb {

// Compute kernels (the harness's kernel contract, harness/vulkan_harness.hpp).
inline constexpr int kKernelInputBinding = 0;   // MbIn: the records, std430
inline constexpr int kKernelOutputBinding = 1;  // MbOut: the results, std430
// An engine kernel's MaterialParamsBlock (std140), mirrored by the C++ header's struct.
inline constexpr int kKernelParamsBinding = 2;
// The sampled textures of a kernel the harness runs, in the order given to
// VulkanHarness::run(). Only an engine kernel has a parameter block, and the harness runs
// none, so the two never meet in one kernel.
inline constexpr int kKernelFirstTextureBinding = 2;
// A validation probe's lookup table (the LTC table that rectangle and disk lights read), a
// readonly std430 float buffer the harness binds whole to every chunk. No probe samples
// textures or has a parameter block, so this never meets either in one kernel.
inline constexpr int kKernelTableBinding = 2;

// Fragment shaders: interface version 2 (docs/fragment-stage.md).
inline constexpr int kFragmentInterfaceVersion = 2;
inline constexpr int kFragmentParamsBinding = 0;       // the material's parameters, std140
inline constexpr int kFragmentFrameBinding = 1;        // MbFrameBlock (engine_frame.glsl)
inline constexpr int kFragmentPrefilteredBinding = 2;  // samplerCube, ibl_* environments
inline constexpr int kFragmentDfgBinding = 3;          // sampler2D, ibl_lut
inline constexpr int kFragmentLtcBinding = 4;          // sampler2D, the LTC table: rect and disk lights
inline constexpr int kFirstTextureBinding = 5;         // sampler2D per texture record

}  // namespace mb
