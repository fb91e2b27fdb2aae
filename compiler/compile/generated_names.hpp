// Every identifier the code generated for a material declares or uses where a user's name
// lands (a user parameter becomes a parameter of materialInputs() and evaluateMaterial(), a
// member of MaterialParams and the probe's local p_<name>): derived from the emitted code
// itself, so that the loader's name check (load/glsl_names.hpp) refuses exactly what would
// collide, and grows with the library and the emitter without a list to keep in step. In
// compile/ because it parses the emitted code with glslang; the loader reaches it through the
// source this file registers (load/generated_names_source.hpp).
#pragma once
#include <map>
#include <string>

#include "library/shader_library.hpp"
#include "load/generated_names_source.hpp"
#include "load/material_desc.hpp"

namespace mb {

// name -> what it is, for the message ("used in the generated evaluateMaterial()", "a
// function of common/geometry.glsl", "a macro of the generated code", "the probe's local
// 'p_n'"). `material` needs its model, features and bricks; its parameters and surface code
// are not read: the code is emitted for a placeholder user parameter and an empty surface()
// in every permutation the material can have (each environment mode with all the model's
// lights, fp32 and fp16; the probe, the engine kernel, its fragment shader and the bench
// probe). Found there:
//  - globals of the emitted code (functions, variables, constants, structs, interface
//    blocks) from glslang's AST (compile/glsl_declarations.hpp) of the fp32 probes and one
//    fragment shader, cached per emitted text;
//  - every macro any of its lines defines;
//  - every identifier in the lines the emitter writes itself (not after a '.': a member),
//    which are the wrapper functions the user's names share a scope with, their locals and
//    the built-in functions they call;
//  - X for each of those named p_X or q_X (the probe's and the bench probe's local of a
//    parameter X).
// The model's input names are left out: a parameter of that name is the model's input.
// Never throws: a permutation that cannot be emitted or parsed contributes what it can.
std::map<std::string, GeneratedName> generatedIdentifiers(const ShaderLibrary& lib, const MaterialDesc& material);

}  // namespace mb
