// Writes GLSL text and keeps #line directives right: included library sources map back to
// their own file and line, and generated lines map to the generated file itself, so any
// compiler message points at the file a person would edit.
#pragma once
#include <string>

#include "core/glsl_float.hpp"  // glslFloat, for the writers of generated GLSL

namespace mb {

class GlslWriter {
 public:
  explicit GlslWriter(std::string displayName) : displayName_(std::move(displayName)) {}
  void line(const std::string& text);  // one generated line (no trailing newline)
  void blank() { line(""); }
  // Inserts `text` from `sourcePath`, whose first line is line `firstLine` there, then
  // returns to the generated file's own numbering.
  void include(const std::string& sourcePath, const std::string& text, int firstLine = 1);
  const std::string& str() const { return out_; }

 private:
  std::string displayName_;
  std::string out_;
  int lines_ = 0;  // lines written so far
};

// The record buffers of the harness's kernel contract (harness/vulkan_harness.hpp): MbIn and
// MbOut at their bindings, their floats qualified by `precision` ("" or "highp ").
void writeKernelBuffers(GlslWriter& w, const std::string& precision = "");

// `text` as one line of a `//` comment or of a #line file name: a newline or carriage return
// would end the comment and make the rest of a path code (any control character is written
// \xNN, as is '"', which would end the #line string), and a trailing backslash would splice the
// next line into the comment (GLSL 4.50 spec 3.1 line continuation): a space follows it.
std::string oneLineText(const std::string& text);

}  // namespace mb
