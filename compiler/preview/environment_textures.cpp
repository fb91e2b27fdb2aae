#include "preview/environment_textures.hpp"

namespace mb::preview {

std::shared_ptr<harness::GpuTexture> uploadEnvironmentCube(harness::VulkanHarness& gpu, const EnvironmentMaps& env) {
  std::vector<harness::TextureLevel> levels;
  for (const CubeLevel& l : env.levels) levels.push_back({l.size, l.size, l.rgba});
  return harness::uploadTexture(gpu, true, levels);
}

std::vector<float> dfgLutTexels(const lut::LutTable& table) {
  std::vector<float> rgba;
  rgba.reserve(size_t{table.size} * table.size * 4);
  for (uint32_t j = 0; j < table.size; ++j)
    for (uint32_t i = 0; i < table.size; ++i)
      rgba.insert(rgba.end(), {table.at(i, j, 0), table.at(i, j, 1), table.at(i, j, 2), 1.0f});
  return rgba;
}

std::shared_ptr<harness::GpuTexture> uploadDfgLut(harness::VulkanHarness& gpu, const lut::LutTable& table) {
  return harness::uploadTexture(gpu, false, {{table.size, table.size, dfgLutTexels(table)}});
}

std::shared_ptr<harness::GpuTexture> uploadLtcTable(harness::VulkanHarness& gpu, const ProbeLtcTable& tables) {
  return harness::uploadTexture(gpu, false, {{4 * tables.table.size, tables.table.size, tables.texels}});
}

}  // namespace mb::preview
