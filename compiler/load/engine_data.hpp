// What an engine needs to draw a material that its shader does not compute (docs/gltf.md
// "Engine data"): for a glTF material, the drawing state and where each texture input's texel
// comes from. Typed here; the package manifest's "engine" object is its only serialized form
// (write/manifest_json.cpp), and the fragment stage binds the textures from it
// (emit/fragment_textures.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace mb {

// Where an engine gets the value of one texture parameter input.
struct TextureBinding {
  std::string param;       // the user parameter, e.g. "baseColorTexture" (empty: no parameter,
                           // the engine applies it to the shading frame: normalTexture)
  std::string channels;    // what the parameter holds: "rgb", "r", "g" or "a" of the texel
  bool srgb = false;       // the image is sRGB-encoded: sample it through an sRGB view
  int texture = -1;        // index into glTF `textures`
  int image = -1;          // its `source` image (-1: none, e.g. given by a texture extension)
  std::string uri;         // the image's uri, or "bufferView N" for an embedded image
  int texCoord = 0;        // which TEXCOORD_n set
  bool transform = false;  // KHR_texture_transform present: the engine applies it to the UVs
  // KHR_texture_transform's values (its defaults when absent): uv' = T(offset) R(rotation)
  // S(scale) uv, with texCoord overriding the textureInfo's when >= 0.
  double offset[2] = {0.0, 0.0};
  double rotation = 0.0;
  double uvScale[2] = {1.0, 1.0};
  int transformTexCoord = -1;
  double scale = 1.0;  // normalTexture scale / occlusionTexture strength, else 1
  // The name the manifest and the fragment stage give it: the parameter, or "normalTexture".
  std::string parameterName() const { return param.empty() ? "normalTexture" : param; }
};

struct EngineData {
  int gltfMaterial = 0;  // position in glTF `materials`
  // Drawing state the engine applies (glTF 2.0 spec, "Alpha Coverage", "Double Sided").
  std::string alphaMode = "OPAQUE";
  double alphaCutoff = 0.5;
  bool doubleSided = false;
  std::vector<TextureBinding> textures;  // in the order of the fragment stage's bindings
  // The anisotropy direction's rotation (KHR_materials_anisotropy), with that feature only.
  std::optional<double> anisotropyRotation;
};

}  // namespace mb
