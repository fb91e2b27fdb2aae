// Generates the DFG LUT on the GPU: emit the kernel from the bricks, compile it in-process
// (compile/), run it on the Vulkan harness with one record per texel.
#pragma once
#include <cstdint>

#include "harness/vulkan_harness.hpp"
#include "lut/dfg_lut.hpp"
#include "lut/lut_kernel.hpp"

namespace mb::lut {

struct GpuLut {
  LutTable table;
  double compileMs = 0;  // emit + glslang + spirv-opt
  // Timestamped time of the LUT dispatches. A one-record warm-up dispatch runs first so
  // that a driver compiling at the first dispatch (lavapipe JIT-compiles there) is timed
  // apart, in warmupGpuMs.
  double gpuMs = 0;
  double warmupGpuMs = 0;
  bool gpuTimestamps = true;  // false: host-measured submit-to-fence time (no timestamps)
  uint32_t chunks = 0;
  size_t spirvInstructions = 0;
};

// samples == 0: the deterministic quadrature kernel (the default of `matbricks lut`);
// samples > 0: Filament's Hammersley estimators with that many points per texel.
GpuLut generateDfgLutOnGpu(harness::VulkanHarness& gpu, const ShaderLibrary& lib, uint32_t size, uint32_t samples);

}  // namespace mb::lut
