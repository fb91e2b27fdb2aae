#include "core/json_document.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace mb {

SourceLocation locationOfOffset(const std::string& text, size_t offset, const std::string& file) {
  SourceLocation loc{file, 1, 1};
  for (size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++loc.line;
      loc.column = 1;
    } else {
      ++loc.column;
    }
  }
  return loc;
}

std::string JsonDocument::escape(const std::string& token) {
  std::string out;
  for (char c : token) {
    if (c == '~')
      out += "~0";
    else if (c == '/')
      out += "~1";
    else
      out += c;
  }
  return out;
}

namespace {

// Walks valid JSON text and records positions. It never needs to report errors itself:
// nlohmann has already accepted the text.
class PositionScanner {
 public:
  PositionScanner(const std::string& text, std::map<std::string, size_t>& values, std::map<std::string, size_t>& keys)
      : t_(text), values_(values), keys_(keys) {}

  void run() {
    skipSpace();
    value("");
  }

 private:
  void skipSpace() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }
  std::string stringToken() {  // at the opening quote; returns the decoded-enough key
    std::string s;
    ++i_;
    while (i_ < t_.size() && t_[i_] != '"') {
      if (t_[i_] == '\\') {
        s += t_[i_++];
      }
      if (i_ < t_.size()) s += t_[i_++];
    }
    ++i_;
    return s;
  }
  void value(const std::string& ptr) {
    values_[ptr] = i_;
    if (i_ >= t_.size()) return;
    char c = t_[i_];
    if (c == '{') {
      ++i_;
      skipSpace();
      while (i_ < t_.size() && t_[i_] != '}') {
        size_t keyPos = i_;
        std::string raw = stringToken();
        // Keys with escapes are rare in our formats; decode them through nlohmann.
        std::string key = nlohmann::json::parse("\"" + raw + "\"").get<std::string>();
        std::string child = ptr + "/" + JsonDocument::escape(key);
        keys_[child] = keyPos;
        skipSpace();
        ++i_;  // ':'
        skipSpace();
        value(child);
        skipSpace();
        if (i_ < t_.size() && t_[i_] == ',') {
          ++i_;
          skipSpace();
        }
      }
      ++i_;
    } else if (c == '[') {
      ++i_;
      skipSpace();
      size_t index = 0;
      while (i_ < t_.size() && t_[i_] != ']') {
        value(ptr + "/" + std::to_string(index++));
        skipSpace();
        if (i_ < t_.size() && t_[i_] == ',') {
          ++i_;
          skipSpace();
        }
      }
      ++i_;
    } else if (c == '"') {
      stringToken();
    } else {
      while (i_ < t_.size() && std::string_view(",]} \t\r\n").find(t_[i_]) == std::string_view::npos) ++i_;
    }
  }

  const std::string& t_;
  std::map<std::string, size_t>& values_;
  std::map<std::string, size_t>& keys_;
  size_t i_ = 0;
};

// nlohmann reports the last byte of the offending token; people expect its first.
size_t tokenStart(const std::string& text, size_t last) {
  if (last >= text.size()) return text.empty() ? 0 : text.size() - 1;
  if (text[last] == '"' && last > 0) {
    for (size_t i = last; i-- > 0;) {
      if (text[i] == '"' && (i == 0 || text[i - 1] != '\\')) return i;
      if (text[i] == '\n') break;
    }
    return last;
  }
  auto wordChar = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '+';
  };
  size_t i = last;
  while (i > 0 && wordChar(text[i]) && wordChar(text[i - 1])) --i;
  return i;
}

}  // namespace

// PositionScanner recurses once per nesting level, so a hostile file of a million '[' would
// overflow the stack: every JSON input (library, material, glTF) is refused beyond
// `maxDepth` before anything recursive runs.
static void checkNestingDepth(const std::string& text, const std::string& file, int maxDepth) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > maxDepth)
        throw DiagnosticError({{Severity::Error, "E-JSON-SYNTAX", locationOfOffset(text, i, file),
                                "JSON nested deeper than " + std::to_string(maxDepth) + " levels", ""}});
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

JsonDocument JsonDocument::parse(const std::string& text, const std::string& file, int maxDepth) {
  checkNestingDepth(text, file, maxDepth);
  JsonDocument doc;
  doc.file_ = file;
  try {
    doc.root_ = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte is 1-based and points just past the offending character.
    size_t offset = tokenStart(text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 3, column 5:
    // syntax error while parsing object - unexpected '}'; expected string literal"
    auto pos = what.find("syntax error");
    std::string msg = pos != std::string::npos ? what.substr(pos) : what;
    throw DiagnosticError(
        {{Severity::Error, "E-JSON-SYNTAX", locationOfOffset(text, offset, file), "invalid JSON: " + msg, ""}});
  } catch (const nlohmann::json::out_of_range& e) {
    // A number literal beyond a double (e.g. 1e999): nlohmann reports it without a position;
    // the literal it quotes is found in the text.
    std::string what = e.what();
    size_t q0 = what.find('\''), q1 = q0 == std::string::npos ? q0 : what.find('\'', q0 + 1);
    std::string literal = q1 == std::string::npos ? "" : what.substr(q0 + 1, q1 - q0 - 1);
    size_t offset = literal.empty() ? std::string::npos : text.find(literal);
    throw DiagnosticError(
        {{Severity::Error, "E-JSON-SYNTAX",
          offset == std::string::npos ? SourceLocation{file, 1, 1} : locationOfOffset(text, offset, file),
          "invalid JSON: number " + (literal.empty() ? std::string("literal") : "'" + literal + "'") +
              " is out of the range of a double",
          ""}});
  }
  std::map<std::string, size_t> values, keys;
  PositionScanner(text, values, keys).run();
  std::vector<size_t> lineStarts{0};
  for (size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') lineStarts.push_back(i + 1);
  auto at = [&](size_t off) {
    auto it = std::upper_bound(lineStarts.begin(), lineStarts.end(), off);
    size_t line = static_cast<size_t>(it - lineStarts.begin());
    return SourceLocation{file, static_cast<int>(line), static_cast<int>(off - lineStarts[line - 1] + 1)};
  };
  for (auto& [p, off] : values) doc.values_[p] = at(off);
  for (auto& [p, off] : keys) doc.keys_[p] = at(off);
  return doc;
}

JsonDocument JsonDocument::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw DiagnosticError(
        {{Severity::Error, "E-FILE-NOT-FOUND", {path, 0, 0}, "cannot open file: expected a readable JSON file", ""}});
  }
  std::stringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

SourceLocation JsonDocument::valueAt(const std::string& pointer) const {
  std::string p = pointer;
  while (true) {
    auto it = values_.find(p);
    if (it != values_.end()) return it->second;
    if (p.empty()) return {file_, 1, 1};
    p = p.substr(0, p.rfind('/'));
  }
}

SourceLocation JsonDocument::keyAt(const std::string& pointer) const {
  auto it = keys_.find(pointer);
  return it != keys_.end() ? it->second : valueAt(pointer);
}

}  // namespace mb
