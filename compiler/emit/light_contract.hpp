// Each light type's part of the GLSL contract (docs/models.md "GLSL contract"): the light
// struct of shaderlib/common/lights.glsl and the entry point a permutation exports for it.
// The emitter, the fragment shader and the include's comment all take the names from here.
#pragma once
#include <string>

#include "core/light_type.hpp"

namespace mb {

// "DirectionalLight", "PointLight", "SpotLight", "SphereLight", "TubeLight".
std::string lightStructName(LightType t);
// "shade" + the struct's name: shadeDirectionalLight, shadePointLight, ...
std::string lightEntryPoint(LightType t);

}  // namespace mb
