#include "load/glsl_names.hpp"

#include <set>

namespace mb {

namespace {

// GLSL 4.50 (and ESSL 3.x) keywords and reserved words, spec section 3.6. Sampler and image
// types are matched by their shape below instead of listed one by one.
const std::set<std::string>& glslWords() {
  static const std::set<std::string> words = {
      // keywords
      "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict", "readonly",
      "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch", "sample", "break",
      "continue", "do", "for", "while", "switch", "case", "default", "if", "else", "subroutine", "in", "out", "inout",
      "float", "double", "int", "void", "bool", "true", "false", "invariant", "precise", "discard", "return", "mat2",
      "mat3", "mat4", "dmat2", "dmat3", "dmat4", "mat2x2", "mat2x3", "mat2x4", "dmat2x2", "dmat2x3", "dmat2x4",
      "mat3x2", "mat3x3", "mat3x4", "dmat3x2", "dmat3x3", "dmat3x4", "mat4x2", "mat4x3", "mat4x4", "dmat4x2", "dmat4x3",
      "dmat4x4", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "dvec2", "dvec3",
      "dvec4", "uint", "uvec2", "uvec3", "uvec4", "lowp", "mediump", "highp", "precision", "struct", "sampler",
      "samplerShadow", "subpassInput", "isubpassInput", "usubpassInput", "subpassInputMS", "isubpassInputMS",
      "usubpassInputMS", "texture2D", "texture3D",
      // reserved for future use
      "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this", "resource",
      "goto", "inline", "noinline", "public", "static", "extern", "external", "interface", "long", "short", "half",
      "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3", "hvec4", "fvec2", "fvec3", "fvec4",
      "sampler3DRect", "filter", "sizeof", "cast", "namespace", "using",
      // the fp16 types our fp16 rewrite emits (GL_EXT_shader_explicit_arithmetic_types)
      "float16_t", "f16vec2", "f16vec3", "f16vec4", "f16mat2", "f16mat3", "f16mat4"};
  return words;
}

// sampler2D, isampler2DArray, image3D, uimageCube, samplerCubeArrayShadow, texture2DMS, ...
bool isOpaqueTypeName(const std::string& name) {
  static const char* const kBases[] = {"sampler", "isampler", "usampler", "image",   "iimage",
                                       "uimage",  "texture",  "itexture", "utexture"};
  static const std::set<std::string> kShapes = {"1D",
                                                "2D",
                                                "3D",
                                                "Cube",
                                                "2DRect",
                                                "1DArray",
                                                "2DArray",
                                                "CubeArray",
                                                "Buffer",
                                                "2DMS",
                                                "2DMSArray",
                                                "1DShadow",
                                                "2DShadow",
                                                "2DRectShadow",
                                                "1DArrayShadow",
                                                "2DArrayShadow",
                                                "CubeShadow",
                                                "CubeArrayShadow"};
  for (const char* base : kBases) {
    std::string b = base;
    if (name.size() > b.size() && name.compare(0, b.size(), b) == 0 && kShapes.count(name.substr(b.size())))
      return true;
  }
  return false;
}

// Identifiers of the generated materialInputs() / evaluateMaterial() (compiler/emit/emitter.cpp):
// a user parameter of one of these names would redeclare or shadow them.
const std::set<std::string>& apiNames() {
  static const std::set<std::string> names = {"m",  "p",     "f",   "n",           "v",       "l",
                                              "px", "light", "env", "illuminance", "surface", "unused_"};
  return names;
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

}  // namespace

std::string reservedNameReason(const std::string& name) {
  if (glslWords().count(name) || isOpaqueTypeName(name)) return "a GLSL keyword or reserved word";
  if (startsWith(name, "gl_") || name.find("__") != std::string::npos)
    return "reserved by GLSL (names starting with 'gl_' or containing '__')";
  if (startsWith(name, "mb_") || startsWith(name, "MB_"))
    return "reserved for matbricks' generated code (names starting with 'mb_' or 'MB_')";
  if (apiNames().count(name)) return "already used by the generated materialInputs()/evaluateMaterial()";
  return {};
}

}  // namespace mb
