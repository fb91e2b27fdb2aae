// compile: the HLSL and MSL engine includes of a permutation (docs/package.md "HLSL and MSL
// includes"), made from the same emitted GLSL as its GLSL include, so the three cannot drift
// (DESIGN.md "One source, many languages"):
//   1. a GLSL "shell": the include's code, the fetch hooks defined with placeholder bodies,
//      and a main() that calls every contract function;
//   2. glslang -> SPIR-V with no spirv-opt, so no function is inlined and every one keeps
//      its name (glslang's OpName is the plain GLSL name);
//   3. SPIRV-Cross to HLSL (shader model 6.0, as the hlsl target) and MSL (2.3);
//   4. of the output, the structs, SPIRV-Cross's helpers and the functions reachable from the
//      contract are kept; the hooks become prototypes the engine defines; the shell's entry
//      point and its globals are dropped.
// Each include is then checked in a wrapper of its language (includeWrapper): HLSL through
// glslang's HLSL front end as a pixel shader, MSL by checkMslInclude.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "compile/source_items.hpp"
#include "core/target.hpp"

namespace mb {

// The contract's public functions (docs/models.md "GLSL contract"), in calling order; a
// permutation has those of its lights and environment.
const std::vector<std::string>& contractFunctionNames();
// The texture-fetch hooks an engine defines (needed by the IBL environments and, the LTC table's,
// by rectangle and disk lights).
const std::vector<std::string>& fetchHookNames();

enum class IncludeLanguage { Glsl, Hlsl, Msl };

// The include bodies of one emitted permutation (Engine mode, probe included or not) for the
// targets among `targets` that have an include of their own (TargetInfo::includeExtension:
// hlsl, msl): target name -> text (no header comment, no guard).
// Throws DiagnosticError (E-TARGET-FAILED naming `displayName`) when a step or check fails.
std::map<std::string, std::string> crossCompileIncludes(const std::string& glsl, const std::vector<Target>& targets,
                                                        const std::string& displayName);

// The contract functions that `code` (an include body in any language) defines, in
// contractFunctionNames() order.
std::vector<FunctionSignature> contractFunctions(const std::string& code);
// The contract functions that `glsl` (the emitted permutation) defines and `body` does not.
std::vector<std::string> missingContractFunctions(const std::string& glsl, const std::string& body);
// The fetch hooks that `code` declares without defining them.
std::vector<FunctionSignature> hookPrototypes(const std::string& code);

// A minimal shader of `language` around an include body: the hooks defined, and an entry
// point that calls every contract function with values derived from its input and returns
// the sum of the radiance they return. HLSL: pixel shader `main` (SV_Position -> SV_Target);
// MSL: `fragment float4 mbWrapperMain`. (The GLSL form is the shell of step 1.)
std::string includeWrapper(const std::string& body, IncludeLanguage language);

// The structural check of an MSL include wrapper (no Metal compiler runs on Debian): braces,
// parentheses and brackets balance, <metal_stdlib> is included, every contract function the
// include declares is defined once, every hook is declared by the include and defined by the
// wrapper, and there is exactly one fragment entry point. "" when it passes, else why not.
std::string checkMslInclude(const std::string& wrapper);

}  // namespace mb
