// Draws a DrawJob (draw_job.hpp) with OpenGL 4.5 core or OpenGL ES 3.1 on EGL's surfaceless
// platform, in a context of its own per call (gl_context.hpp, the one GlCompute uses): the GLSL
// 450 and ESSL 3.10 (or 3.00) fragment shaders of a permutation compiled by the driver's own
// GLSL compiler and drawn, as the preview draws the SPIR-V with Vulkan (docs/preview.md
// "Targets"). Colour targets are RGBA32F (EXT_color_buffer_float on ES), read back as floats.
#pragma once
#include "glrun/draw_job.hpp"
#include "glrun/gl_compute.hpp"

namespace mb::gl {

// Throws GlError: no context of `api` (as GlCompute), the driver's first compile or link
// message for a shader it rejects ("the driver's GLSL compiler rejected the fragment shader: ..."),
// a missing extension, an incomplete framebuffer, a GL error; a job GL would draw wrongly without
// an error ("malformed draw job: ...": an index past the vertices, a texture level not half the
// one above it), refused before any GL call; a draw without contents for a uniform block the
// program reads, refused before drawing. Vulkan's clip depth 0..1 is kept with glClipControl
// (core in 4.5; on ES GL_EXT_clip_control, when the driver has it, as llvmpipe does).
DrawResult drawOnGl(GlApi api, const DrawJob& job);

}  // namespace mb::gl
