// Writes GLSL text and keeps #line directives right: included library sources map back to
// their own file and line, and generated lines map to the generated file itself, so any
// compiler message points at the file a person would edit.
#pragma once
#include <string>

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

// A float literal that round-trips through fp32 and is always a valid GLSL float
// ("1.0", "0.04", "1e-05").
std::string glslFloat(double value);

}  // namespace mb
