#include "core/diagnostics.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace mb {

SourceLocation::SourceLocation() = default;
SourceLocation::SourceLocation(std::string f, int l, int c) : file(std::move(f)), line(l), column(c) {}

Diagnostic::Diagnostic() = default;
Diagnostic::Diagnostic(Severity s, std::string c, SourceLocation w, std::string m, std::string sg)
    : severity(s), code(std::move(c)), where(std::move(w)), message(std::move(m)), suggestion(std::move(sg)) {}

std::string formatLocation(const SourceLocation& where) {
  std::string out = where.file.empty() ? std::string("<input>") : where.file;
  if (where.line > 0) {
    out += ":" + std::to_string(where.line);
    if (where.column > 0) out += ":" + std::to_string(where.column);
  }
  return out;
}

std::string formatDiagnostic(const Diagnostic& d) {
  std::string out = formatLocation(d.where);
  out += d.severity == Severity::Error ? ": error[" : ": warning[";
  out += d.code + "]: " + d.message;
  if (!d.suggestion.empty()) out += " (" + d.suggestion + ")";
  // Keep the promise of one line per diagnostic.
  std::replace(out.begin(), out.end(), '\n', ' ');
  return out;
}

std::string diagnosticsToJson(const std::vector<Diagnostic>& ds) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& d : ds) {
    arr.push_back({{"severity", d.severity == Severity::Error ? "error" : "warning"},
                   {"code", d.code},
                   {"file", d.where.file},
                   {"line", d.where.line},
                   {"column", d.where.column},
                   {"message", d.message},
                   {"suggestion", d.suggestion}});
  }
  // Messages quote the input, which may not be UTF-8 (a binary file's bytes): replace such
  // bytes with U+FFFD instead of throwing, which would end the CLI with terminate().
  return arr.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

static std::string joinDiagnostics(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) {
    if (!s.empty()) s += "\n";
    s += formatDiagnostic(d);
  }
  return s;
}

DiagnosticError::DiagnosticError(std::vector<Diagnostic> diags)
    : std::runtime_error(joinDiagnostics(diags)), diags_(std::move(diags)) {}

void DiagnosticSink::error(std::string code, SourceLocation where, std::string message, std::string suggestion) {
  diags_.push_back({Severity::Error, std::move(code), std::move(where), std::move(message), std::move(suggestion)});
}

void DiagnosticSink::warning(std::string code, SourceLocation where, std::string message, std::string suggestion) {
  diags_.push_back({Severity::Warning, std::move(code), std::move(where), std::move(message), std::move(suggestion)});
}

bool DiagnosticSink::hasErrors() const {
  return std::any_of(diags_.begin(), diags_.end(), [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

void DiagnosticSink::throwIfErrors() const {
  if (hasErrors()) throw DiagnosticError(diags_);
}

static size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      size_t sub = prev[j - 1] + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::vector<std::string> closestMatches(const std::string& word, const std::vector<std::string>& candidates,
                                        size_t maxCount) {
  std::vector<std::pair<size_t, std::string>> scored;
  for (const auto& c : candidates) {
    size_t d = editDistance(word, c);
    // Substring hits ("ggx" in "d_ggx") count as close too.
    bool contains = !word.empty() && c.find(word) != std::string::npos;
    size_t limit = std::max<size_t>(2, std::max(word.size(), c.size()) / 2);
    if (d <= limit || contains) scored.emplace_back(contains ? std::min(d, size_t(1)) : d, c);
  }
  std::stable_sort(scored.begin(), scored.end());
  std::vector<std::string> out;
  for (size_t i = 0; i < scored.size() && out.size() < maxCount; ++i) out.push_back(scored[i].second);
  return out;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates) {
  auto m = closestMatches(word, candidates);
  if (m.empty()) return {};
  std::string s = "did you mean ";
  for (size_t i = 0; i < m.size(); ++i) s += (i ? ", '" : "'") + m[i] + "'";
  return s + "?";
}

}  // namespace mb
