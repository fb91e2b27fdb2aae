#pragma once
#include <string>

#include "library/shader_library.hpp"

namespace mb {

// "float mb_d_ggx(Geometry g, float alpha)": the brick's GLSL signature, from its slot.
std::string brickSignature(const Brick& brick, const Slot& slot);

}  // namespace mb
