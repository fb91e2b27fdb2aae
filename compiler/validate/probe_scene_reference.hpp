// The double-precision mirror of the probe scene's GLSL (compiler/emit/probe_scene.cpp):
// builds the reference's frame, lights and environment from the same fp32 record.
#pragma once
#include "common/model_reference.hpp"
#include "emit/emitter.hpp"

namespace mb {

// Where each of a scene's inputs sits in a record (offsets; the scene's inputs only), found
// once per permutation so that a record is read without looking names up.
struct SceneColumns {
  uint32_t n = 0, v = 0, l = 0, ngTilt = 0, tangentAngle = 0, illuminance = 0;
  uint32_t pointDistance = 0, pointIntensity = 0, pointFalloffRadius = 0;
  uint32_t spotAxisAngle = 0, spotCosOuter = 0, spotInnerFraction = 0, spotDistance = 0, spotIntensity = 0,
           spotFalloffRadius = 0;
  uint32_t sphereDistance = 0, sphereRadiusFraction = 0, sphereIntensity = 0, sphereFalloffRadius = 0;
  uint32_t tubeAxisAngle = 0, tubeDistance = 0, tubeAxisTilt = 0, tubeHalfLengthFraction = 0, tubeRadiusFraction = 0,
           tubeIntensity = 0, tubeFalloffRadius = 0;
  // Rectangle and disk lights: [0] rect, [1] disk.
  uint32_t areaLuminance[2] = {}, areaDistance[2] = {}, areaAxisAngle[2] = {}, areaTilt[2] = {}, areaHalfWidth[2] = {},
           areaHalfHeight[2] = {};
  uint32_t ltcM00 = 0, ltcM02 = 0, ltcM20 = 0, ltcM22 = 0, ltcNorm = 0, ltcFresnel = 0;
  uint32_t ltcSheenM00 = 0, ltcSheenM02 = 0, ltcSheenM20 = 0, ltcSheenM22 = 0, ltcSheenNorm = 0;
  uint32_t sh[9] = {}, ao = 0, prefiltered = 0, dfgX = 0, dfgY = 0, dfgZ = 0;
};
// Throws std::logic_error when the layout lacks one of the scene's inputs.
SceneColumns sceneColumns(const ProbeScene& scene, const ProbeLayout& layout);

// Fills in.frame, the lights and the environment of `scene` from `record` (laid out as
// `layout`).
void sceneFromRecord(const ProbeScene& scene, const ProbeLayout& layout, const double* record, ref::ModelEvalInput& in);
// The same from columns found once.
void sceneFromRecord(const ProbeScene& scene, const SceneColumns& columns, const double* record,
                     ref::ModelEvalInput& in);

}  // namespace mb
