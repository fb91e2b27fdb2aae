// The precision (core/precision.hpp), quality (core/quality.hpp), environment
// (core/environment_mode.hpp) and light (core/light_type.hpp) axes, and the targets
// (core/target.hpp), in the bottom layer so that
// the library's manifest reader, the loaders (a scene names them), permute (the axes), compile
// (a target's outputs) and write (the package) all take them from one place instead of asking
// a later stage. Which light types and environment modes a model shades, its manifest declares.
#pragma once
#include "core/environment_mode.hpp"  // EnvironmentMode, allEnvironmentModes()
#include "core/light_type.hpp"        // LightType, allLightTypes()
#include "core/precision.hpp"         // Precision, allPrecisions()
#include "core/quality.hpp"           // Quality, allQualities()
#include "core/target.hpp"            // Target, its TargetInfo row, allTargets()
