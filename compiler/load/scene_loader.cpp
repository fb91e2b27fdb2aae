// INTERIM (replaced by the scene loader).
#include "load/scene_desc.hpp"

namespace mb {

std::vector<std::string> SceneDesc::lightTypes() const { return {}; }
SceneDesc loadScene(const std::string& path, const ShaderLibrary&) {
  throw DiagnosticError({{Severity::Error, "E-SCENE", {path, 0, 0}, "scenes not implemented yet"}});
}
SceneDesc parseSceneJson(const std::string&, const std::string& file, const ShaderLibrary&) {
  throw DiagnosticError({{Severity::Error, "E-SCENE", {file, 0, 0}, "scenes not implemented yet"}});
}

}  // namespace mb
