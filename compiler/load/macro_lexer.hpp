// Tokens of one macro-form directive line (docs/macro-form.md "Lexical rules"): identifiers,
// numbers (GLSL float literals, finite), "strings", ( , ) and the end of the line; `//` starts
// a comment. Anything else is an Invalid token that says what is wrong, so the parser can
// report it at its column and go on with the next line.
#pragma once
#include <string>
#include <vector>

namespace mb {

struct MacroToken {
  enum class Kind { Identifier, Number, String, LParen, RParen, Comma, End, Invalid };
  Kind kind = Kind::End;
  std::string text;     // as written; for String the decoded contents; for Invalid the problem
  int column = 0;       // 1-based, in the physical line
  double number = 0.0;  // Number only
};

// Tokens of `line` from byte `start` on; always ends with one End (or stops at the first
// Invalid token, which is then last).
std::vector<MacroToken> tokenizeDirective(const std::string& line, size_t start);

// "'x'" for a token in a message: its text, clipped, or "the end of the line".
std::string describeToken(const MacroToken& t);

}  // namespace mb
