#include "lut/lut_gpu.hpp"

#include <chrono>

#include "compile/glsl_compiler.hpp"

namespace mb::lut {

GpuLut generateDfgLutOnGpu(harness::VulkanHarness& gpu, const ShaderLibrary& lib, uint32_t size, uint32_t samples) {
  GpuLut out;
  auto t0 = std::chrono::steady_clock::now();
  EmittedShader shader = samples == 0 ? emitDfgQuadratureKernel(lib) : emitDfgLutKernel(lib, samples);
  CompileResult compiled = compileComputeGlsl(shader.glsl, shader.fileName);
  out.compileMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  out.spirvInstructions = spirvInstructionCount(compiled.spirv);

  auto kernel = gpu.createKernel(compiled.spirv);
  const uint32_t inStride = shader.layout.inStride, outStride = shader.layout.outStride;
  std::vector<float> inputs = texelInputs(size);
  std::vector<float> warmupRecord(inputs.begin(), inputs.begin() + inStride);
  out.warmupGpuMs = gpu.run(*kernel, warmupRecord, inStride, outStride, 1).gpuMs;

  uint64_t count = static_cast<uint64_t>(size) * size;
  harness::RunResult run = gpu.run(*kernel, inputs, inStride, outStride, count);
  out.gpuMs = run.gpuMs;
  out.gpuTimestamps = run.gpuTimestamps;
  out.chunks = run.chunks;
  out.table.size = size;
  out.table.samples = samples;
  out.table.values = std::move(run.outputs);
  return out;
}

}  // namespace mb::lut
