#include "emit/fragment_textures.hpp"

#include <nlohmann/json.hpp>

namespace mb {

std::vector<FragmentTexture> fragmentTextures(const MaterialDesc& material) {
  std::vector<FragmentTexture> out;
  if (material.engineData.empty()) return out;
  // engineData is our own glTF import's output (load/gltf_import.cpp engineData), so a parse
  // failure is a bug, and nlohmann's exception says so.
  const nlohmann::json data = nlohmann::json::parse(material.engineData);
  if (!data.contains("textures")) return out;
  for (const auto& t : data.at("textures")) {
    FragmentTexture f;
    f.param = t.at("parameter").get<std::string>();
    f.channels = t.at("channels").get<std::string>();
    f.srgb = t.at("srgb").get<bool>();
    f.scale = t.value("scale", 1.0);
    f.binding = kFirstTextureBinding + static_cast<int>(out.size());
    out.push_back(f);
  }
  return out;
}

}  // namespace mb
