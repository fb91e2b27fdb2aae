// The double-precision mirror of the probe scene's GLSL (compiler/emit/probe_scene.cpp):
// builds the reference's frame, lights and environment from the same fp32 record.
#pragma once
#include "common/model_reference.hpp"
#include "emit/emitter.hpp"

namespace mb {

// Fills in.frame, the lights and the environment of `scene` from `record` (laid out as
// `layout`).
void sceneFromRecord(const ProbeScene& scene, const ProbeLayout& layout, const double* record, ref::ModelEvalInput& in);

}  // namespace mb
