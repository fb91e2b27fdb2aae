#include "emit/glsl_writer.hpp"

#include "core/descriptor_bindings.hpp"

namespace mb {

void GlslWriter::line(const std::string& text) {
  out_ += text;
  out_ += '\n';
  ++lines_;
}

void GlslWriter::include(const std::string& sourcePath, const std::string& text, int firstLine) {
  line("#line " + std::to_string(firstLine) + " \"" + oneLineText(sourcePath) + "\"");
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    line(text.substr(start, end - start));
    start = end + 1;
  }
  // The directive names the number of the line that follows it.
  line("#line " + std::to_string(lines_ + 2) + " \"" + displayName_ + "\"");
}

void writeKernelBuffers(GlslWriter& w, const std::string& precision) {
  w.line("layout(std430, set = 0, binding = " + std::to_string(kKernelInputBinding) + ") readonly buffer MbIn { " +
         precision + "float mbIn[]; };");
  w.line("layout(std430, set = 0, binding = " + std::to_string(kKernelOutputBinding) + ") writeonly buffer MbOut { " +
         precision + "float mbOut[]; };");
}

std::string oneLineText(const std::string& text) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  for (char c : text) {
    auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f || c == '"')
      out += std::string("\\x") + kHex[u >> 4] + kHex[u & 0xf];
    else
      out += c;
  }
  if (!out.empty() && out.back() == '\\') out += ' ';
  return out;
}

}  // namespace mb
