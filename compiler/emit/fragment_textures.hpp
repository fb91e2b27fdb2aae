// The texture samplers of a permutation's fragment shader (docs/fragment-stage.md): one per
// texture record of a glTF material (docs/gltf.md "Texture inputs", the manifest's
// engine.textures), in that order, at binding kFirstTextureBinding + i.
#pragma once
#include <string>
#include <vector>

#include "core/descriptor_bindings.hpp"  // kFirstTextureBinding
#include "load/material_desc.hpp"

namespace mb {

struct FragmentTexture {
  std::string param;     // the parameter it feeds; "normalTexture" perturbs the shading normal
  std::string channels;  // "rgb", "r", "g" or "a" of the texel
  bool srgb = false;     // bound through an sRGB view: the sampler returns linear values
  double scale = 1.0;    // normalTexture's scale (the others apply theirs in surface code)
  int binding = 0;       // kFirstTextureBinding + position in the material's records
  bool isNormal() const { return param == "normalTexture"; }
};

// The material's texture bindings (MaterialDesc::engine, from the glTF import); none for JSON
// and macro materials.
std::vector<FragmentTexture> fragmentTextures(const MaterialDesc& material);

}  // namespace mb
