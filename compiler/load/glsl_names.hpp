// Names a material may not give a user parameter: they become GLSL identifiers in the
// generated permutation (members of MaterialParams and parameters of materialInputs() and
// evaluateMaterial(), docs/models.md "GLSL contract").
#pragma once
#include <string>

namespace mb {

// Why `name` cannot be a GLSL identifier of ours, or empty when it can: a GLSL 4.50 keyword or
// reserved word (spec section 3.6), a `gl_` or `__` name (reserved by GLSL), an `mb_`/`MB_`
// name (the emitter's own), or a name the generated API already uses (m, p, n, v, l, ...).
std::string reservedNameReason(const std::string& name);

}  // namespace mb
