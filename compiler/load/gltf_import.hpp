// glTF 2.0 material import (docs/gltf.md): every material of a .gltf or .glb becomes a
// MaterialSource of the library's glTF model (`standard`, with the bricks of
// shaderlib/gltf_defaults.json), with features clearcoat / anisotropy / sheen from
// KHR_materials_clearcoat / _anisotropy / _sheen. Factors become constants; each texture
// becomes a parameter input that carries the sampled texel (the engine samples, the shader
// combines), with generated surface code doing the glTF combination. Only the JSON is read:
// buffers, images and meshes are the engine's.
#pragma once
#include <string>
#include <vector>

#include "core/json_document.hpp"
#include "load/engine_data.hpp"
#include "load/material_desc.hpp"

namespace mb {

struct GltfMaterial {
  MaterialSource source;
  int index = 0;         // position in glTF `materials`
  std::string gltfName;  // as written (may be empty)
  std::vector<TextureBinding> textures;
  // Drawing state the engine applies (glTF 2.0 spec, "Alpha Coverage", "Double Sided") and
  // the anisotropy direction's rotation (KHR_materials_anisotropy), glTF defaults if absent.
  std::string alphaMode = "OPAQUE";
  double alphaCutoff = 0.5;
  bool doubleSided = false;
  double anisotropyRotation = 0.0;
};

// Reads a .gltf / .glb (the container is detected by content) and maps every material.
// Throws DiagnosticError (file:line:column; docs/gltf.md) for malformed files and for
// extensions in extensionsRequired that are not supported. Warnings (unsupported extension
// used, alpha not shaded, ...) go into each MaterialSource::warnings; warnings about the file
// as a whole go to the first material. The model and the bricks bound come from the
// library's glTF defaults (E-GLTF-NO-DEFAULTS when it declares none).
std::vector<GltfMaterial> readGltf(const std::string& path, const ShaderLibrary& lib);
std::vector<GltfMaterial> parseGltf(const std::string& bytes, const std::string& file, const ShaderLibrary& lib);
// The same on a document already read (loadGltfJson / parseGltfJson), for readers that also
// look at other parts of the file (load/scene_gltf.cpp).
// `container` (optional) lets it check a .glb's BIN chunk against the buffer it declares.
struct GltfContainerInfo;
std::vector<GltfMaterial> mapGltfDocument(const JsonDocument& doc, const ShaderLibrary& lib,
                                          const GltfContainerInfo* container = nullptr);

// readGltf without the texture records.
std::vector<MaterialSource> readGltfMaterials(const std::string& path, const ShaderLibrary& lib);

// Reads and resolves every material against the library; collects the diagnostics of all
// materials before throwing once. A file without materials is an error (E-GLTF-NO-MATERIALS):
// there is nothing to compile.
std::vector<MaterialDesc> importGltfMaterials(const std::string& path, const ShaderLibrary& lib);

}  // namespace mb
