#include "load/macro_lexer.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "load/material_resolve.hpp"

namespace mb {

namespace {

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool numberStart(char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-'; }

// A GLSL floating-point or integer literal in decimal: [+-] digits [. digits] [e [+-] digits]
// [f|F] (at least one digit before the exponent). No hex, no nan/inf: a material value is a
// plain number. Returns an empty string when `s` is one, else what is wrong.
std::string checkNumberSyntax(const std::string& s, std::string& digits) {
  size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  size_t mantissa = 0;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++mantissa;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++mantissa;
  }
  if (mantissa == 0) return "expected digits";
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    size_t exp = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++exp;
    if (exp == 0) return "expected digits after the exponent";
  }
  digits = s.substr(s[0] == '+' ? 1 : 0, i - (s[0] == '+' ? 1 : 0));
  if (i < s.size() && (s[i] == 'f' || s[i] == 'F')) ++i;
  if (i != s.size()) return "unexpected '" + std::string(1, s[i]) + "'";
  return {};
}

std::string printable(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return std::string(1, c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
  return buf;
}

}  // namespace

std::vector<MacroToken> tokenizeDirective(const std::string& line, size_t start) {
  std::vector<MacroToken> out;
  auto invalid = [&](size_t at, std::string problem) {
    out.push_back({MacroToken::Kind::Invalid, std::move(problem), static_cast<int>(at + 1)});
    return out;
  };
  size_t i = start;
  while (true) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    int col = static_cast<int>(i + 1);
    if (i >= line.size() || line.compare(i, 2, "//") == 0) {
      out.push_back({MacroToken::Kind::End, "", col});
      return out;
    }
    char c = line[i];
    if (line.compare(i, 2, "/*") == 0) return invalid(i, "block comments are not allowed in directives: use //");
    if (c == '(' || c == ')' || c == ',') {
      auto kind = c == '(' ? MacroToken::Kind::LParen : c == ')' ? MacroToken::Kind::RParen : MacroToken::Kind::Comma;
      out.push_back({kind, std::string(1, c), col});
      ++i;
    } else if (identStart(c)) {
      size_t b = i;
      while (i < line.size() && identChar(line[i])) ++i;
      out.push_back({MacroToken::Kind::Identifier, line.substr(b, i - b), col});
    } else if (numberStart(c)) {
      size_t b = i;
      while (i < line.size() && (identChar(line[i]) || line[i] == '.' || line[i] == '+' || line[i] == '-')) ++i;
      std::string text = line.substr(b, i - b), digits;
      std::string problem = checkNumberSyntax(text, digits);
      if (!problem.empty()) return invalid(b, "malformed number '" + clipped(text) + "': " + problem);
      double x = 0.0;
      auto r = std::from_chars(digits.data(), digits.data() + digits.size(), x);
      if (r.ec != std::errc() || !std::isfinite(x))
        return invalid(b, "number '" + clipped(text) + "' is out of the range of a double");
      out.push_back({MacroToken::Kind::Number, text, col, x});
    } else if (c == '"') {
      std::string s;
      size_t b = i++;
      while (i < line.size() && line[i] != '"') {
        if (line[i] == '\\') {
          if (i + 1 >= line.size() || (line[i + 1] != '"' && line[i + 1] != '\\'))
            return invalid(i, "unknown escape in a string: only \\\" and \\\\ are allowed");
          ++i;
        }
        s += line[i++];
      }
      if (i >= line.size()) return invalid(b, "unterminated string: expected a closing '\"' on this line");
      ++i;
      out.push_back({MacroToken::Kind::String, s, col});
    } else {
      return invalid(i, "unexpected character '" + printable(c) + "'");
    }
  }
}

std::string describeToken(const MacroToken& t) {
  if (t.kind == MacroToken::Kind::End) return "the end of the line";
  if (t.kind == MacroToken::Kind::String) return "a string";
  return "'" + clipped(t.text) + "'";
}

}  // namespace mb
