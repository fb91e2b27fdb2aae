#include "emit/fp16_rewrite.hpp"

#include <cctype>
#include <map>

namespace mb {
namespace {

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

const std::string& halfTypeOf(const std::string& ident) {
  static const std::map<std::string, std::string> types = [] {
    std::map<std::string, std::string> m{{"float", "float16_t"}};
    for (const char* n : {"2", "3", "4"}) {
      m[std::string("vec") + n] = std::string("f16vec") + n;
      m[std::string("mat") + n] = std::string("f16mat") + n;
      for (const char* k : {"2", "3", "4"}) m[std::string("mat") + n + "x" + k] = std::string("f16mat") + n + "x" + k;
    }
    return m;
  }();
  auto it = types.find(ident);
  return it == types.end() ? ident : it->second;
}

class Rewriter {
 public:
  explicit Rewriter(const std::string& in) : in_(in) {}

  std::string run() {
    while (pos_ < in_.size()) {
      if (atLineStart_ && directive()) continue;
      char c = in_[pos_];
      if (c == '/' && peek(1) == '/') {
        copyUntil("\n");
      } else if (c == '/' && peek(1) == '*') {
        copyBlockComment();
      } else if (isIdentStart(c)) {
        identifier();
      } else if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
        number();
      } else {
        put(c);
        ++pos_;
        if (c == '\n')
          atLineStart_ = true;
        else if (!std::isspace(static_cast<unsigned char>(c)))
          atLineStart_ = false;
      }
    }
    return out_;
  }

 private:
  char peek(size_t k) const { return pos_ + k < in_.size() ? in_[pos_ + k] : '\0'; }
  void put(char c) { out_ += c; }

  // A directive line: `#define` bodies are rewritten, every other directive (#line,
  // #version, #extension, #if...) is copied as it is, continuation lines included.
  bool directive() {
    size_t p = pos_;
    while (p < in_.size() && (in_[p] == ' ' || in_[p] == '\t')) ++p;
    if (p >= in_.size() || in_[p] != '#') return false;
    size_t name = p + 1;
    while (name < in_.size() && (in_[name] == ' ' || in_[name] == '\t')) ++name;
    size_t nameEnd = name;
    while (nameEnd < in_.size() && isIdentChar(in_[nameEnd])) ++nameEnd;
    atLineStart_ = false;
    if (in_.compare(name, nameEnd - name, "define") == 0) {
      out_.append(in_, pos_, nameEnd - pos_);
      pos_ = nameEnd;
      return true;  // the body is scanned as ordinary tokens up to the newline
    }
    copyDirectiveLine();
    return true;
  }

  void copyDirectiveLine() {
    while (pos_ < in_.size()) {
      char c = in_[pos_++];
      put(c);
      if (c == '\n') {
        // A backslash before the newline continues the directive.
        size_t n = out_.size();
        bool continued = n >= 2 && out_[n - 2] == '\\';
        if (!continued) break;
      }
    }
    atLineStart_ = true;
  }

  void copyUntil(const char* end) {
    size_t stop = in_.find(end, pos_);
    stop = stop == std::string::npos ? in_.size() : stop;
    out_.append(in_, pos_, stop - pos_);
    pos_ = stop;
  }

  void copyBlockComment() {
    size_t stop = in_.find("*/", pos_ + 2);
    stop = stop == std::string::npos ? in_.size() : stop + 2;
    out_.append(in_, pos_, stop - pos_);
    pos_ = stop;
  }

  void identifier() {
    size_t start = pos_;
    while (pos_ < in_.size() && isIdentChar(in_[pos_])) ++pos_;
    out_ += halfTypeOf(in_.substr(start, pos_ - start));
  }

  // GLSL numeric literals: 12, 12u, 0x1F, 1.0, .5, 1e-4, 2.5f, 1.0lf, 1.0hf.
  void number() {
    size_t start = pos_;
    if (in_[pos_] == '0' && (peek(1) == 'x' || peek(1) == 'X')) {
      pos_ += 2;
      while (pos_ < in_.size() && std::isxdigit(static_cast<unsigned char>(in_[pos_]))) ++pos_;
      while (pos_ < in_.size() && isIdentChar(in_[pos_])) ++pos_;  // u suffix
      out_.append(in_, start, pos_ - start);
      return;
    }
    bool isFloat = false;
    while (pos_ < in_.size() && isDigit(in_[pos_])) ++pos_;
    if (pos_ < in_.size() && in_[pos_] == '.') {
      isFloat = true;
      ++pos_;
      while (pos_ < in_.size() && isDigit(in_[pos_])) ++pos_;
    }
    if (pos_ < in_.size() && (in_[pos_] == 'e' || in_[pos_] == 'E')) {
      size_t e = pos_ + 1;
      if (e < in_.size() && (in_[e] == '+' || in_[e] == '-')) ++e;
      if (e < in_.size() && isDigit(in_[e])) {
        isFloat = true;
        pos_ = e;
        while (pos_ < in_.size() && isDigit(in_[pos_])) ++pos_;
      }
    }
    size_t digitsEnd = pos_;
    while (pos_ < in_.size() && isIdentChar(in_[pos_])) ++pos_;
    std::string suffix = in_.substr(digitsEnd, pos_ - digitsEnd);
    out_.append(in_, start, digitsEnd - start);
    if (suffix == "f" || suffix == "F" || (suffix.empty() && isFloat)) {
      out_ += "hf";
    } else {
      out_ += suffix;  // integers, u, lf (double) and hf stay as written
    }
  }

  const std::string& in_;
  std::string out_;
  size_t pos_ = 0;
  bool atLineStart_ = true;
};

}  // namespace

std::string rewriteToFp16(const std::string& glsl) { return Rewriter(glsl).run(); }

}  // namespace mb
