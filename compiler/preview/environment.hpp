// The preview's environments (docs/environments.md): procedural radiance maps made here,
// never downloaded, prefiltered into a cubemap with mips by our own compute kernels (the GGX
// importance-sampling bricks, Karis 2013 PrefilterEnvMap), with the radiance SH9 projected
// from the same map. The fragment shader samples the cube at binding 2 (docs/fragment-stage.md)
// and the reference render samples it on the CPU through EnvironmentMaps::sample, so that the
// GPU and the reference see the same environment inputs per pixel.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "preview/texel_filter.hpp"

namespace mb {
class ShaderLibrary;
}
namespace mb::harness {
class VulkanHarness;
}

namespace mb::preview {

// One mip level of a cube: 6 faces in Vulkan's layer order (+X, -X, +Y, -Y, +Z, -Z), each
// size x size texels of RGBA32F (A = 1), row-major from the face's (s, t) = (0, 0) texel:
// texel (i, j) of face f is rgba[((f * size + j) * size + i) * 4 + c] and sits at
// s = (i + 0.5) / size, t = (j + 0.5) / size (the Vulkan spec's cube face selection table
// maps (s, t) to a direction; cubeTexelDirection in environment_cube.hpp).
struct CubeLevel {
  uint32_t size = 0;
  std::vector<float> rgba;
};

struct EnvironmentMaps {
  std::string name;  // "studio", "sky"
  // The full mip chain, base size down to 1. Level i is prefiltered at perceptual roughness
  // i / maxMip (alpha = roughness^2): the inverse of the linear mip_mapping brick
  // (mip = roughness * maxMip); level 0 is the radiance at the texel centre.
  std::vector<CubeLevel> levels;
  // Radiance SH9 projected in double from level 0 with exact texel solid angles, rgb per
  // coefficient, in the order of shaderlib/common/lights.glsl and the sh_irradiance bricks:
  // L00, L1-1, L10, L11, L2-2, L2-1, L20, L21, L22 (index l(l+1)+m, real basis of
  // sh9_irradiance.ref.cpp: Y1-1 ~ y, Y10 ~ z, Y11 ~ x).
  double sh[9][3] = {};
  // GGX samples per texel of the prefiltered levels (the kernel's Hammersley count).
  uint32_t samplesPerTexel = 0;

  // levels.size() - 1: the frame block's environment.y (MbFrameBlock, engine_frame.glsl).
  double maxMip() const { return levels.empty() ? 0.0 : static_cast<double>(levels.size() - 1); }
  // What Vulkan's textureLod(samplerCube, dir, lod) returns from this cube uploaded as RGBA32F
  // with the sampler of harness/gpu_texture.hpp (linear min/mag/mip, clamp to edge, seamless
  // cube filtering): face selection by the major axis, trilinear between the two nearest
  // levels, bilinear within a level with texels across an edge taken from the adjacent face,
  // and at a corner the missing texel as the average of the other three. In double; dir
  // need not be normalized. The measured difference from lavapipe is in docs/environments.md.
  std::array<double, 3> sample(const std::array<double, 3>& dir, double lod) const;
  // The same with its sampling bound: how far a device filtering with `filter.limits` may be
  // from it (texel_filter.hpp), or, with a quantizer, what such a device returns.
  FilteredRgb sampleFiltered(const std::array<double, 3>& dir, double lod, const TexelFilter& filter) const;
};

// {"studio", "sky"}.
std::vector<std::string> environmentNames();

// The named environment at `baseSize` texels per face edge (a power of two, 1..2048),
// prefiltered by `lib`'s bricks (the library --shaderlib names), built on `gpu` the first time
// and cached in memory for the process (and on disk in the matbricks cache directory, keyed by
// the kernel source and the parameters). Throws DiagnosticError E-UNKNOWN-ENVIRONMENT (one
// line listing the valid names) for an unknown name.
EnvironmentMaps buildEnvironment(const ShaderLibrary& lib, const std::string& name, harness::VulkanHarness& gpu,
                                 uint32_t baseSize = 128);

}  // namespace mb::preview
