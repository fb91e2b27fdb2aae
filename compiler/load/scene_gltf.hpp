// The scene part of a glTF 2.0 file (docs/scenes.md "glTF scenes"): the KHR_lights_punctual
// lights that nodes of the scene reference, and the materials that mesh primitives of those
// nodes use. Materials no node uses are not resolved, so they cannot fail the scene.
#pragma once
#include <string>
#include <vector>

#include "load/scene_desc.hpp"

namespace mb {

struct GltfSceneContents {
  std::vector<SceneLight> lights;        // in node traversal order
  std::vector<SceneMaterial> materials;  // used ones, in glTF material order
  bool imageBased = false;               // EXT_lights_image_based is used
  std::vector<Diagnostic> warnings;
};

// Throws DiagnosticError (file:line:column) for a malformed file or a used material that
// does not resolve.
GltfSceneContents readGltfScene(const std::string& path, const ShaderLibrary& lib);

}  // namespace mb
