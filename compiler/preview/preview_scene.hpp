// The preview's scene (docs/preview.md): the camera, the lights of each type and the frame
// block (shaderlib/common/engine_frame.glsl) every sphere's fragment shader reads, and the
// same lights in double for the reference render.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/model_reference.hpp"
#include "core/light_type.hpp"
#include "preview/environment.hpp"

namespace mb::preview {

// The camera looks down -z at the unit sphere at the origin from kCameraDistance, y up, with a
// vertical field of view that leaves a margin of ~6% around the sphere. Every sphere is drawn
// at the origin into its own square tile (a viewport per draw), so every sphere of a sweep is
// seen exactly alike.
inline constexpr double kCameraDistance = 4.0;
inline constexpr double kFieldOfViewDegrees = 31.0;

// One light of the frame block, in world space (engine_frame.glsl's record fields).
struct PreviewLight {
  LightType type = LightType::Dir;
  std::array<float, 3> direction{};       // dir: unit, towards the light
  std::array<float, 3> position{};        // local lights; tube: segment start
  std::array<float, 3> end{};             // tube: segment end
  std::array<float, 3> axis{};            // spot: unit axis the spot shines along
  std::array<float, 3> halfX{}, halfY{};  // rect: half edges; disk: semi-axes (emitting towards halfX x halfY)
  std::array<float, 3> intensity{};       // dir: illuminance; rect, disk: luminance; others: luminous intensity
  float radius = 0, falloffRadius = 0;    // sphere, tube radius; local lights' falloff
  float cosOuter = 0, cosInner = 0;       // spot cone
};

// The light types `--lights` names (allLightTypeNames()); throws DiagnosticError E-PREVIEW-LIGHT
// for an unknown name, listing the valid ones.
std::vector<LightType> parsePreviewLights(const std::vector<std::string>& names);
// One light of each given type, placed as docs/preview.md shows (a key light from the upper
// left, the others around the camera).
std::vector<PreviewLight> defaultLights(const std::vector<LightType>& types);

// The frame block's std140 bytes (engine_frame.glsl): camera, lights, the environment's SH9
// and its environment constants (ao = 1, maxMip). `env` null: no environment terms.
std::vector<uint8_t> frameBlockBytes(const std::vector<PreviewLight>& lights, const EnvironmentMaps* env);
// The SH9 coefficients as the frame block holds them (fp32), back in double.
std::array<ref::Vec3, 9> frameSh(const EnvironmentMaps& env);

// Sets in.dir, in.point, ... for the lights of `type` index `k` among `lights` of that type, as
// the fragment shader builds them (positions relative to the shaded point). Returns false if
// there is no k-th light of that type.
bool setLight(const std::vector<PreviewLight>& lights, LightType type, size_t k, const ref::Vec3& worldPos,
              ref::ModelEvalInput& in);

// Largest radiance-scale input of the scene (docs/preview.md "Tolerance"): each directional
// light's largest illuminance channel, each local light's largest intensity channel over its
// squared distance to the sphere's surface, and the environment's largest texel plus the
// largest SH irradiance it can give. Absolute tolerances of a unit-illuminance composition
// scale with it, as validate scales them with the probe scene's bound.
double sceneRadianceBound(const std::vector<PreviewLight>& lights, const EnvironmentMaps* env);

// Column-major world-to-clip matrix (Vulkan clip space: y down, depth 0..1) of the camera.
std::array<float, 16> viewProjection();
std::array<float, 3> cameraPosition();

}  // namespace mb::preview
