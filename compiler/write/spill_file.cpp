#include "write/spill_file.hpp"

#include <vector>

#include "core/diagnostics.hpp"

namespace mb {
namespace {

[[noreturn]] void spillError(const std::string& what) {
  throw DiagnosticError({{Severity::Error, "E-IO", {"temporary file", 0, 0}, what, "check TMPDIR and free space"}});
}

}  // namespace

SpillFile::SpillFile() : file_(std::tmpfile()) {
  if (!file_) spillError("cannot create a temporary file for the package's manifest and header");
}

SpillFile::~SpillFile() { std::fclose(file_); }

void SpillFile::append(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) spillError("cannot write a temporary file");
  size_ += text.size();
}

void SpillFile::copyTo(std::ostream& out) const {
  if (std::fflush(file_) != 0 || std::fseek(file_, 0, SEEK_SET) != 0) spillError("cannot read a temporary file");
  std::vector<char> buffer(1 << 16);
  size_t left = size_;
  while (left > 0) {
    const size_t n = std::fread(buffer.data(), 1, std::min(buffer.size(), left), file_);
    if (n == 0) spillError("cannot read a temporary file");
    out.write(buffer.data(), static_cast<std::streamsize>(n));
    left -= n;
  }
  // Appends go to the end again.
  if (std::fseek(file_, 0, SEEK_END) != 0) spillError("cannot read a temporary file");
}

}  // namespace mb
