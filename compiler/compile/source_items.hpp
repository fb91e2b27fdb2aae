// compile: a reader of the C-like sources that glslang and SPIRV-Cross print (GLSL, HLSL,
// MSL), enough to cut a cross-compiled module into its top-level items and to read a
// function's signature (engine_includes.hpp). Not a parser of those languages: it relies on
// SPIRV-Cross's formatting (one item per line group, braces never inside comments or
// strings, no string literals at all).
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace mb {

// One top-level item: a preprocessor line, a declaration ending in ';', a struct, or a
// function definition, with its text (lines joined, each ending in '\n').
struct SourceItem {
  std::string text;
};

// The top-level items of `source`, in order; blank lines between them are dropped.
std::vector<SourceItem> topLevelItems(const std::string& source);

struct FunctionParam {
  std::string type;  // as written, e.g. "thread const float3&", "inout ShadingPixel", "vec3"
  std::string name;
};

struct FunctionSignature {
  std::string returnType;
  std::string name;
  std::vector<FunctionParam> params;
  std::string text;      // "ret name(params)", as written
  bool defined = false;  // a body follows (else a prototype)
};

// The signature of function `name` in `text` (a top-level item, or a whole GLSL source whose
// functions start at the beginning of a line), or nullopt when `text` declares no such
// function.
std::optional<FunctionSignature> findFunction(const std::string& text, const std::string& name);

// The bare type of a parameter: address space, const, in/out qualifiers and '&' removed
// ("thread const float3&" -> "float3", "inout ShadingPixel" -> "ShadingPixel").
std::string bareType(const std::string& paramType);

}  // namespace mb
