// Draws a DrawJob (draw_job.hpp) with OpenGL 4.5 core or OpenGL ES 3.1 on EGL's surfaceless
// platform, the context gl_compute.hpp makes: the GLSL 450 and ESSL 3.10 fragment shaders of a
// permutation compiled by the driver's own GLSL compiler and drawn, as the preview draws the
// SPIR-V with Vulkan (docs/preview.md "Targets"). Colour targets are RGBA32F
// (EXT_color_buffer_float on ES), read back as floats.
#pragma once
#include "glrun/draw_job.hpp"
#include "glrun/gl_compute.hpp"

namespace mb::gl {

// Throws GlError: no context of `api` (as GlCompute), the driver's first compile or link
// message for a shader it rejects, a missing extension, an incomplete framebuffer, a GL error.
DrawResult drawOnGl(GlApi api, const DrawJob& job);

}  // namespace mb::gl
