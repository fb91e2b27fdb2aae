#include "load/glsl_names.hpp"

#include <cctype>
#include <set>

#include "core/cpp_identifiers.hpp"

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

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

}  // namespace

std::string reservedNameReason(const std::string& name) {
  if (glslWords().count(name) || isOpaqueTypeName(name)) return "a GLSL keyword or reserved word";
  if (startsWith(name, "gl_") || name.find("__") != std::string::npos)
    return "reserved by GLSL (names starting with 'gl_' or containing '__')";
  if (startsWith(name, "mb_") || startsWith(name, "MB_"))
    return "reserved for matbricks' generated code (names starting with 'mb_' or 'MB_')";
  // A user parameter is read as a member (p.name, mbParams.name): glslang takes `.length` for
  // the method of arrays and vectors (GLSL 4.50 spec 5.9) and rejects it on a struct.
  if (name == "length") return "the GLSL method .length(), which a member of that name would hide";
  // The package's C++ header declares every parameter as a member of its parameter struct.
  if (isCppKeyword(name)) return "a C++ keyword (the package's C++ header declares the parameter as a struct member)";
  return {};
}

std::string reservedNameReason(const std::string& name, const std::map<std::string, GeneratedName>& generated) {
  std::string reason = reservedNameReason(name);
  if (!reason.empty()) return reason;
  auto it = generated.find(name);
  return it == generated.end() ? std::string() : "already used by the generated code (" + it->second.what + ")";
}

std::vector<DeclaredName> globalNamesOf(const std::string& glsl) {
  std::vector<DeclaredName> out;
  auto isStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto isPart = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  auto add = [&](const DeclaredName& d) {
    if (d.name.empty() || glslWords().count(d.name) || isOpaqueTypeName(d.name)) return;
    for (const auto& o : out)
      if (o.name == d.name) return;
    out.push_back(d);
  };
  int line = 0, column = 1, braces = 0, parens = 0;
  bool lineStart = true, declaratorDone = false, structNext = false;
  DeclaredName last;
  auto resetStatement = [&] {
    declaratorDone = false;
    structNext = false;
    last = {};
  };
  for (size_t i = 0; i < glsl.size();) {
    const char c = glsl[i];
    auto advance = [&](size_t n) {
      for (size_t k = 0; k < n && i < glsl.size(); ++k, ++i) {
        if (glsl[i] == '\n') {
          ++line;
          column = 1;
        } else {
          ++column;
        }
      }
    };
    if (c == '\n') {
      lineStart = true;
      advance(1);
      continue;
    }
    if (c == '/' && i + 1 < glsl.size() && glsl[i + 1] == '/') {
      while (i < glsl.size() && glsl[i] != '\n') advance(1);
      continue;
    }
    if (c == '/' && i + 1 < glsl.size() && glsl[i + 1] == '*') {
      size_t end = glsl.find("*/", i + 2);
      advance(end == std::string::npos ? glsl.size() - i : end + 2 - i);
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      advance(1);
      continue;
    }
    if (c == '#' && lineStart) {
      // A directive: only #define declares a name.
      advance(1);
      while (i < glsl.size() && (glsl[i] == ' ' || glsl[i] == '\t')) advance(1);
      const bool define = glsl.compare(i, 6, "define") == 0;
      if (define) {
        advance(6);
        while (i < glsl.size() && (glsl[i] == ' ' || glsl[i] == '\t')) advance(1);
        DeclaredName d{{}, line, column, true};
        while (i < glsl.size() && isPart(glsl[i])) {
          d.name += glsl[i];
          advance(1);
        }
        if (!d.name.empty() && isStart(d.name[0])) out.push_back(d);
      }
      while (i < glsl.size() && glsl[i] != '\n') advance(1);
      continue;
    }
    lineStart = false;
    if (isStart(c)) {
      DeclaredName d{{}, line, column, false};
      while (i < glsl.size() && isPart(glsl[i])) {
        d.name += glsl[i];
        advance(1);
      }
      if (braces || parens) continue;
      if (d.name == "struct") {
        structNext = true;
      } else if (structNext) {
        add(d);
        structNext = false;
      } else {
        last = d;
      }
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      while (i < glsl.size() && (isPart(glsl[i]) || glsl[i] == '.')) advance(1);
      continue;
    }
    const bool top = braces == 0 && parens == 0;
    const bool assignment = c == '=' && !(i + 1 < glsl.size() && glsl[i + 1] == '=');
    // `layout(...)` and the like: a qualifier, not the declared name.
    const bool keyword = last.name.empty() || glslWords().count(last.name) || isOpaqueTypeName(last.name);
    if (top && !declaratorDone && !keyword && (c == '(' || c == '[' || c == ';' || c == ',' || assignment)) {
      add(last);
      if (c != ',') declaratorDone = true;
    }
    if (c == '(') ++parens;
    if (c == ')' && parens > 0) --parens;
    if (c == '{') ++braces;
    if (c == '}' && braces > 0 && --braces == 0) resetStatement();
    if (c == ';' && top) resetStatement();
    advance(1);
  }
  return out;
}

}  // namespace mb
