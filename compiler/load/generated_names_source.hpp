// What the resolver needs from a later stage: the identifiers the code generated for a
// material declares or uses where a user's name lands, so that a user parameter or surface
// name that would collide is refused at the user's line (load/glsl_names.hpp). Only emitting
// and parsing the code can say (compile/generated_names.hpp); load may not depend on emit or
// compile, so that stage registers itself here as the source, and load asks through it.
#pragma once
#include <map>
#include <string>

#include "library/shader_library.hpp"
#include "load/material_desc.hpp"

namespace mb {

struct GeneratedName {
  std::string what;  // for the message
  // Only ever a local or parameter of a generated function (`b`, `f`, `px`, the probe's p_x):
  // a global of the same name in user surface code is shadowed there, not redefined.
  bool localOnly = false;
};

using GeneratedNamesSource = std::map<std::string, GeneratedName> (*)(const ShaderLibrary& lib,
                                                                      const MaterialDesc& material);

// Called once, during static initialization, by the stage that derives the names.
void setGeneratedNamesSource(GeneratedNamesSource source);

// The registered source's answer for `material`. Throws std::logic_error when no source is
// linked into the program: a silent empty answer would let colliding names through.
std::map<std::string, GeneratedName> generatedNamesOf(const ShaderLibrary& lib, const MaterialDesc& material);

}  // namespace mb
