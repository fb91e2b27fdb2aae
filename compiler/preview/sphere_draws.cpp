#include "preview/sphere_draws.hpp"

#include <algorithm>
#include <cstring>

#include "emit/fragment_shader.hpp"
#include "permute/permutation.hpp"
#include "preview/sphere_mesh.hpp"

namespace mb::preview {
namespace {

// std140 (GLSL 4.50 spec 7.6.2.2) of the fragment shader's MbMaterialParams: float aligned to
// 4, vec2 to 8, vec3 to 16 bytes; the block's size rounded up to 16.
std::vector<uint8_t> paramsBlock(const MaterialDesc& m, const SphereParams& values) {
  std::vector<uint8_t> bytes;
  size_t offset = 0;
  for (const auto& prm : m.params) {
    if (prm.constant) continue;
    const int n = componentCount(prm.type);
    const size_t align = n == 1 ? 4 : (n == 2 ? 8 : 16);
    offset = (offset + align - 1) / align * align;
    bytes.resize(offset + 4 * n, 0);
    for (int k = 0; k < n; ++k) {
      const float f = static_cast<float>(values.at(prm.name)[k]);
      std::memcpy(bytes.data() + offset + 4 * k, &f, 4);
    }
    offset += 4 * n;
  }
  bytes.resize((bytes.size() + 15) / 16 * 16, 0);
  return bytes;
}

}  // namespace

SphereDraws sphereDraws(const PreviewOptions& o, const MaterialDesc& m, const std::vector<SphereParams>& spheres,
                        const std::vector<PreviewLight>& lights, EnvironmentMode environmentMode,
                        const EnvironmentMaps& environment) {
  SphereDraws d;
  d.tile = o.size;
  d.width = o.size * static_cast<uint32_t>(spheres.size());
  d.height = o.size;
  d.mesh = uvSphere();
  // Every sphere sits at the origin with radius 1, so the model matrix is the identity, which the
  // vertex shader applies exactly (its normal matrix, the inverse transpose, is the identity too).
  const auto vp = viewProjection();
  d.vertexBlock.resize(128);
  const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  std::memcpy(d.vertexBlock.data(), identity, 64);
  std::memcpy(d.vertexBlock.data() + 64, vp.data(), 64);
  d.frame = frameBlockBytes(lights, environmentMode == EnvironmentMode::None ? nullptr : &environment);
  for (const auto& s : spheres) d.params.push_back(paramsBlock(m, s));
  d.prefiltered = isIbl(environmentMode);
  d.dfg = usesDfgLut(environmentMode);
  d.ltc =
      std::any_of(lights.begin(), lights.end(), [&](const PreviewLight& l) { return lightReadsLtcTable(m, l.type); });
  return d;
}

}  // namespace mb::preview
