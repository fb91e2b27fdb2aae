#include "emit/fragment_textures.hpp"

namespace mb {

std::vector<FragmentTexture> fragmentTextures(const MaterialDesc& material) {
  std::vector<FragmentTexture> out;
  if (!material.engine) return out;
  for (const TextureBinding& t : material.engine->textures) {
    FragmentTexture f;
    f.param = t.parameterName();
    f.channels = t.channels;
    f.srgb = t.srgb;
    f.scale = t.scale;
    f.binding = kFirstTextureBinding + static_cast<int>(out.size());
    out.push_back(f);
  }
  return out;
}

}  // namespace mb
