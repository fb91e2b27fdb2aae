// The names of the precision and quality axes and of the targets, in the bottom layer so that
// the library's manifest reader, the loaders (a scene names them), permute (the axes), compile
// (a target's outputs) and write (the package) all take them from one place instead of asking
// a later stage. Light types and environment modes are the library's
// (library/shader_library.hpp): the manifest declares which a model shades.
#pragma once
#include <string>
#include <vector>

namespace mb {

const std::vector<std::string>& allPrecisions();     // fp32, fp16
const std::vector<std::string>& allQualityLevels();  // low, medium, high
// Target names, in package order: spirv, glsl450, essl310, hlsl, msl (compile/targets.hpp).
const std::vector<std::string>& allTargets();

}  // namespace mb
