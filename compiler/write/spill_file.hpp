// write: text too large to keep in memory while a package streams (the manifest's entries and
// the header's tables of 10^5 permutations), appended to an anonymous temporary file
// (tmpfile(3): removed when closed, or when the process dies) and copied out once at the end.
#pragma once
#include <cstdio>
#include <ostream>
#include <string>

namespace mb {

class SpillFile {
 public:
  SpillFile();  // throws DiagnosticError (E-IO) when no temporary file can be made
  ~SpillFile();
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;

  void append(const std::string& text);
  // Everything appended so far, in order; throws E-IO on a read or write failure.
  void copyTo(std::ostream& out) const;
  size_t size() const { return size_; }

 private:
  std::FILE* file_;
  size_t size_ = 0;
};

}  // namespace mb
