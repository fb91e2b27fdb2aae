// The precision (core/precision.hpp) and quality (core/quality.hpp) axes, and the targets (core/target.hpp), in the bottom layer so that
// the library's manifest reader, the loaders (a scene names them), permute (the axes), compile
// (a target's outputs) and write (the package) all take them from one place instead of asking
// a later stage. Light types and environment modes are the library's
// (library/shader_library.hpp): the manifest declares which a model shades.
#pragma once
#include "core/precision.hpp"  // Precision, allPrecisions()
#include "core/quality.hpp"    // Quality, allQualities()
#include "core/target.hpp"     // Target, its TargetInfo row, allTargets()
