// The glTF 2.0 containers: a .gltf file is JSON text; a .glb file is a 12-byte header, a JSON
// chunk and an optional BIN chunk (glTF 2.0 spec, "GLB File Format Specification"). Material
// import needs only the JSON, so the BIN chunk is located (its length checked) but not read.
#pragma once
#include <cstdint>
#include <string>

#include "core/json_document.hpp"

namespace mb {

// Reads `path` and parses its JSON with source positions. The container is chosen by content,
// not by extension: a file starting with the GLB magic "glTF" is binary. Errors throw
// DiagnosticError:
//   E-FILE-NOT-FOUND, E-JSON-SYNTAX (at line:column of the JSON text; for a .glb, of the
//   JSON chunk's text), E-GLB-HEADER / E-GLB-CHUNK / E-GLB-TRUNCATED (binary structure; the
//   position is line 1, column = byte offset + 1, and the message names the byte offset).
JsonDocument loadGltfJson(const std::string& path);
// The same, on bytes already read (`file` is used in diagnostics).
JsonDocument parseGltfJson(const std::string& bytes, const std::string& file);

// What the container says besides the JSON: whether it is a .glb and, if so, the length of
// its BIN chunk (-1: none), which the import compares with the buffer the JSON declares.
struct GltfContainerInfo {
  bool glb = false;
  int64_t binChunkLength = -1;
};
JsonDocument loadGltfJson(const std::string& path, GltfContainerInfo& info);
// The same for material import, which reads only the top-level members asset, buffers,
// extensions, extensionsRequired, extensionsUsed, images, materials, samplers and textures: the
// values of all others (nodes, meshes, accessors, animations: most of a large glTF's JSON) are
// checked as JSON but never enter the tree. Positions are those of the file.
JsonDocument loadGltfMaterialJson(const std::string& path, GltfContainerInfo& info);
// The same for the scene walk (load/scene_gltf.cpp), which also reads scene, scenes, meshes and
// nodes, and of each node only children, extensions and mesh: a node's other members are
// blanked, and a node with none of those is read as an empty object.
JsonDocument loadGltfSceneJson(const std::string& path, GltfContainerInfo& info);
JsonDocument parseGltfJson(const std::string& bytes, const std::string& file, GltfContainerInfo& info);

// Builds a .glb: header, JSON chunk (padded with spaces) and, if `bin` is not empty, a BIN
// chunk (padded with zeros), as the spec lays them out. Used to generate the shipped .glb
// examples and the malformed-binary tests.
std::string packGlb(const std::string& json, const std::string& bin = {});

}  // namespace mb
