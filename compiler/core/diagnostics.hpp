// Diagnostics: every user-facing error carries a code, a file:line:column, what was
// expected, and a suggestion where one exists. Stages collect several before failing.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace mb {

struct SourceLocation {
  // Out-of-line constructors: brace-initialized temporaries of these aggregates trip GCC 12's
  // false-positive -Wmaybe-uninitialized/-Wrestrict inside std::string.
  SourceLocation();
  SourceLocation(std::string file, int line = 0, int column = 0);
  std::string file;
  int line = 0;    // 1-based; 0 = unknown
  int column = 0;  // 1-based; 0 = unknown
};

enum class Severity { Error, Warning };

struct Diagnostic {
  Diagnostic();
  Diagnostic(Severity severity, std::string code, SourceLocation where, std::string message,
             std::string suggestion = {});
  Severity severity = Severity::Error;
  std::string code;  // stable id, e.g. "E-JSON-SYNTAX", "E-UNKNOWN-BRICK"
  SourceLocation where;
  std::string message;     // what is wrong and what was expected
  std::string suggestion;  // "did you mean 'd_ggx'?" or empty
};

// "file:line:col: error[CODE]: message (did you mean ...)" on one line.
std::string formatDiagnostic(const Diagnostic& d);
// "file:line:column" as formatDiagnostic writes it: the line and column only where known, and
// "<input>" for a location without a file.
std::string formatLocation(const SourceLocation& where);
std::string diagnosticsToJson(const std::vector<Diagnostic>& ds);

// Thrown by a stage when it has collected at least one error.
class DiagnosticError : public std::runtime_error {
 public:
  explicit DiagnosticError(std::vector<Diagnostic> diags);
  const std::vector<Diagnostic>& diagnostics() const { return diags_; }

 private:
  std::vector<Diagnostic> diags_;
};

class DiagnosticSink {
 public:
  void error(std::string code, SourceLocation where, std::string message, std::string suggestion = {});
  void warning(std::string code, SourceLocation where, std::string message, std::string suggestion = {});
  bool hasErrors() const;
  const std::vector<Diagnostic>& all() const { return diags_; }
  // Throws DiagnosticError if any error was collected.
  void throwIfErrors() const;

 private:
  std::vector<Diagnostic> diags_;
};

// Closest candidates to `word` by edit distance (at most `maxCount`, only reasonably close
// ones), for "did you mean" suggestions.
std::vector<std::string> closestMatches(const std::string& word, const std::vector<std::string>& candidates,
                                        size_t maxCount = 3);
// "did you mean 'a', 'b'?" or empty.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace mb
