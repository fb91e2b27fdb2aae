// Internal to glTF import: mapping one glTF material object to a GltfMaterial
// (gltf_mapping.cpp), given the file-level facts gltf_import.cpp has checked.
#pragma once
#include <set>
#include <string>
#include <vector>

#include "core/json_fields.hpp"
#include "library/shader_library.hpp"
#include "load/gltf_import.hpp"

namespace mb::gltf {

// What every material of a file shares.
struct FileContext {
  explicit FileContext(const GltfDefaults& d) : defaults(d) {}
  std::string file;
  std::string stem;                // file name without directory and extension
  std::set<std::string> required;  // extensionsRequired (already reported if unsupported)
  size_t textureCount = 0;         // size of `textures` (0 if absent or malformed)
  size_t imageCount = 0;           // size of `images`
  // The library's model and bricks for glTF materials (shaderlib/gltf_defaults.json).
  const GltfDefaults& defaults;
};

// Extensions a material may use that the import maps (docs/gltf.md).
bool isMaterialExtensionSupported(const std::string& name);
// Extensions the import understands anywhere in a file: the material ones, those it records
// for the engine (KHR_texture_transform) or leaves to the scene import (KHR_lights_punctual,
// EXT_lights_image_based), and the mesh/image ones only the engine decodes (Draco, BasisU,
// ...), which no material reads. None of them is an error in extensionsRequired.
bool isExtensionUnderstood(const std::string& name);
// All of them, for messages.
std::vector<std::string> understoodExtensions();

// Maps materials[index]. Errors go to the sink (the caller throws once); warnings go to the
// material. `usedExtensions` collects the unsupported extensions the material uses.
GltfMaterial mapMaterial(JsonFields& f, const FileContext& ctx, size_t index, std::set<std::string>& usedExtensions);

// "Material.001" -> "Material_001": [A-Za-z0-9_] kept, other runs become one '_', a leading
// digit or reserved GLSL prefix ("gl_") gets a "material_" prefix; empty stays empty.
std::string identifierFrom(const std::string& name);

}  // namespace mb::gltf
