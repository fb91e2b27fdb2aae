// Names a material may not give a user parameter: they become GLSL identifiers in the
// generated permutation (members of MaterialParams, parameters of materialInputs() and
// evaluateMaterial(), the probe's p_<name> locals; docs/models.md "GLSL contract").
#pragma once
#include <map>
#include <string>
#include <vector>

#include "load/generated_names_source.hpp"

namespace mb {

// Why `name` cannot be a GLSL identifier of ours, or empty when it can, by the fixed rules: a
// GLSL 4.50 keyword or reserved word (spec section 3.6), a `gl_` or `__` name (reserved by
// GLSL), an `mb_`/`MB_` name (the emitter's own), `length` (GLSL's .length() method: it cannot
// be read as a member), a C++ keyword (a member of the C++ header's parameter struct).
std::string reservedNameReason(const std::string& name);
// The same, then `generated`: the identifiers the code generated for the material declares or
// uses where the name goes (compile/generated_names.hpp, through load/generated_names_source.hpp), name -> what it is.
std::string reservedNameReason(const std::string& name, const std::map<std::string, GeneratedName>& generated);

// A name user surface code declares at global scope, where: `line` counts from 0 within the
// code, `column` from 1 within that line.
struct DeclaredName {
  std::string name;
  int line = 0;
  int column = 1;
  bool macro = false;  // #define'd
};
// The macros (#define), functions, structs and global variables `glsl` declares: a token scan
// at brace and parenthesis depth 0, comments skipped, GLSL keywords left out. A declaration
// list `float a = 1.0, b;` yields its first name only: what it finds is refused when the
// generated code uses it, and a later name glslang still reports at the user's own line.
std::vector<DeclaredName> globalNamesOf(const std::string& glsl);

}  // namespace mb
