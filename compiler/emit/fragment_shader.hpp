// Emit: a permutation's fragment shader (docs/fragment-stage.md), the same emitted library
// code as the compute kernel (emitPermutation cut at `#ifndef MB_NO_PROBE`, as the GLSL
// include is) plus a fragment main() over the stable interface of version 1: world-space
// attributes at locations 0-3, the material parameters at set 0 binding 0, the frame block
// (shaderlib/common/engine_frame.glsl) at binding 1, the environment samplers at 2 and 3 and
// the material's textures from binding 4.
#pragma once
#include "core/descriptor_bindings.hpp"  // the fragment stage's bindings
#include "emit/emitter.hpp"

namespace mb {

// GLSL 450 (Vulkan) fragment shader of `perm`; fileName "<key>.frag" ("<key>.mediump.frag"
// with `mediump`, the fp16 form for targets without 16-bit types, as emitPermutation's).
// The layout is the emitted shader's with the probe's records, i.e. no inputs.
// Throws DiagnosticError as emitPermutation does.
EmittedShader emitFragmentShader(const ShaderLibrary& lib, const Permutation& perm, bool mediump = false);
// The same from the permutation's Engine kernel as emitPermutation(lib, perm, false,
// EmitMode::Engine, mediump) returned it (the build has it already).
EmittedShader fragmentShaderOf(const ShaderLibrary& lib, const Permutation& perm, const EmittedShader& kernel,
                               bool mediump);

}  // namespace mb
