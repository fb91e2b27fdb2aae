#include "core/json_document.hpp"

#include <algorithm>
#include <cctype>
#include <functional>

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

using nlohmann::json;

// Walks valid JSON text together with the tree nlohmann built from it and records where each
// object member's key and value start. It never needs to report errors itself: nlohmann has already
// accepted the text. A key that occurs twice names one node (the later value wins, as in the
// tree); the later position is kept.
class PositionScanner {
 public:
  PositionScanner(const std::string& text, std::vector<JsonDocument::Position>& out) : t_(text), out_(out) {}

  uint32_t run(const json& root) {
    skipSpace();
    const auto at = static_cast<uint32_t>(i_);
    value(&root);
    return at;
  }

 private:
  void skipSpace() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }
  // At the opening quote: the key as the tree holds it (escapes decoded by nlohmann; they are
  // rare in our formats).
  std::string key() {
    const size_t start = ++i_;
    bool escaped = false;
    while (i_ < t_.size() && t_[i_] != '"') {
      if (t_[i_] == '\\') {
        escaped = true;
        ++i_;
      }
      ++i_;
    }
    std::string raw = t_.substr(start, i_ - start);
    ++i_;
    return escaped ? json::parse("\"" + raw + "\"").get<std::string>() : raw;
  }
  void skipString() {
    ++i_;
    while (i_ < t_.size() && t_[i_] != '"') i_ += t_[i_] == '\\' ? 2 : 1;
    ++i_;
  }
  void separator() {
    skipSpace();
    if (i_ < t_.size() && t_[i_] == ',') {
      ++i_;
      skipSpace();
    }
  }
  // `node`: the tree's node for this text, or null inside a value a repeated key replaced.
  void value(const json* node) {
    if (i_ >= t_.size()) return;
    const char c = t_[i_];
    if (c == '{') {
      ++i_;
      skipSpace();
      while (i_ < t_.size() && t_[i_] != '}') {
        const auto keyPos = static_cast<uint32_t>(i_);
        const std::string name = key();
        const json* child = nullptr;
        if (node && node->is_object())
          if (auto it = node->find(name); it != node->end()) child = &*it;
        skipSpace();
        ++i_;  // ':'
        skipSpace();
        record(child, keyPos);
        value(child);
        separator();
      }
      ++i_;
    } else if (c == '[') {
      ++i_;
      skipSpace();
      for (size_t index = 0; i_ < t_.size() && t_[i_] != ']'; ++index) {
        // Elements get no entry: their positions are found from the array's when asked for
        // (JsonDocument::elementOffset), so a long array of numbers costs nothing here.
        value(node && node->is_array() && index < node->size() ? &(*node)[index] : nullptr);
        separator();
      }
      ++i_;
    } else if (c == '"') {
      skipString();
    } else {
      while (i_ < t_.size() && std::string_view(",]} \t\r\n").find(t_[i_]) == std::string_view::npos) ++i_;
    }
  }
  void record(const json* node, uint32_t keyPos) {
    if (node) out_.push_back({node, static_cast<uint32_t>(i_), keyPos});
  }

 public:
 private:
  const std::string& t_;
  std::vector<JsonDocument::Position>& out_;
  size_t i_ = 0;
};

// Object members: the nodes that get a Position.
size_t memberCount(const json& node) {
  size_t n = node.is_object() ? node.size() : 0;
  if (node.is_structured())
    for (const auto& child : node) n += memberCount(child);
  return n;
}

// Sorted by node, one entry per node: of a repeated key's, the later in the text (in place:
// no second buffer the size of the table).
void sortPositions(std::vector<JsonDocument::Position>& ps) {
  std::sort(ps.begin(), ps.end(), [](const auto& a, const auto& b) {
    return a.node != b.node ? std::less<>()(a.node, b.node) : a.value < b.value;
  });
  size_t kept = 0;
  for (size_t i = 0; i < ps.size(); ++i) {
    if (i + 1 < ps.size() && ps[i + 1].node == ps[i].node) continue;
    ps[kept++] = ps[i];
  }
  ps.resize(kept);
}

// Visits `from` and `to`, two equal trees, node by node.
void copyPositions(const json& from, const json& to,
                   const std::function<const JsonDocument::Position*(const json*)>& find,
                   std::vector<JsonDocument::Position>& out) {
  if (!from.is_structured()) return;
  auto a = from.begin();
  auto b = to.begin();
  for (; a != from.end(); ++a, ++b) {
    if (const auto* p = find(&*a)) out.push_back({&*b, p->value, p->key});
    copyPositions(*a, *b, find, out);
  }
}

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
// `maxDepth` before anything recursive runs. Values are counted as their separators and
// openers (',' and '[' '{' outside strings: at least one per value but the first).
static void checkStructure(const std::string& text, const std::string& file, int maxDepth, size_t maxValues) {
  int depth = 0;
  size_t values = 1;
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
    if (!inString && (c == ',' || c == '[' || c == '{') && ++values > maxValues)
      throw DiagnosticError({{Severity::Error, "E-FILE-TOO-LARGE", locationOfOffset(text, i, file),
                              "more than " + std::to_string(maxValues) +
                                  " JSON values: no file of this kind holds that many (its tree would take "
                                  "~100 bytes of memory per value)",
                              ""}});
  }
}

JsonDocument JsonDocument::parse(std::string text, const std::string& file, int maxDepth, size_t maxValues) {
  checkStructure(text, file, maxDepth, maxValues);
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
  doc.positions_.reserve(memberCount(doc.root_));
  doc.rootOffset_ = PositionScanner(text, doc.positions_).run(doc.root_);
  sortPositions(doc.positions_);
  constexpr size_t kBlock = 4096;
  uint32_t lines = 0, lineStart = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (i % kBlock == 0) {
      doc.blockLines_.push_back(lines);
      doc.blockLineStart_.push_back(lineStart);
    }
    if (text[i] == '\n') {
      ++lines;
      lineStart = static_cast<uint32_t>(i + 1);
    }
  }
  doc.text_ = std::move(text);
  return doc;
}

JsonDocument JsonDocument::load(const std::string& path, const InputKind& kind) {
  return parse(readInputFileOrThrow(path, kind), path);
}

JsonDocument::JsonDocument(const JsonDocument& other)
    : root_(other.root_),
      file_(other.file_),
      text_(other.text_),
      rootOffset_(other.rootOffset_),
      blockLines_(other.blockLines_),
      blockLineStart_(other.blockLineStart_) {
  positions_.reserve(other.positions_.size());
  copyPositions(
      other.root_, root_, [&](const json* n) { return other.positionOf(n); }, positions_);
  sortPositions(positions_);
}

JsonDocument& JsonDocument::operator=(const JsonDocument& other) {
  if (this != &other) *this = JsonDocument(other);
  return *this;
}

const JsonDocument::Position* JsonDocument::positionOf(const json* node) const {
  auto it = std::lower_bound(positions_.begin(), positions_.end(), node,
                             [](const Position& p, const json* n) { return std::less<>()(p.node, n); });
  return it != positions_.end() && it->node == node ? &*it : nullptr;
}

uint32_t JsonDocument::elementOffset(uint32_t array, size_t index) const {
  size_t i = skipJsonSpace(text_, array + 1);
  for (size_t k = 0; k < index && i < text_.size(); ++k) {
    i = skipJsonSpace(text_, skipJsonValue(text_, i));
    i = skipJsonSpace(text_, i + 1);  // past ','
  }
  return static_cast<uint32_t>(i);
}

JsonDocument::Found JsonDocument::find(const std::string& pointer) const {
  const json* node = &root_;
  Found found{rootOffset_, kNoOffset, true};
  size_t at = 0;
  while (at < pointer.size()) {  // pointer[at] == '/'
    const size_t end = std::min(pointer.find('/', at + 1), pointer.size());
    std::string token = pointer.substr(at + 1, end - at - 1);
    for (size_t k = token.find('~'); k != std::string::npos; k = token.find('~', k + 1))
      token.replace(k, 2, token.compare(k, 2, "~1") == 0 ? "/" : "~");
    const Position* member = nullptr;
    if (node->is_object()) {
      auto it = node->find(token);
      member = it != node->end() ? positionOf(&*it) : nullptr;
      if (!member) break;
      found = {member->value, member->key, true};
      node = &*it;
    } else if (node->is_array() && !token.empty() && token.find_first_not_of("0123456789") == std::string::npos &&
               token.size() < 10 && std::stoul(token) < node->size()) {
      const size_t index = std::stoul(token);
      found = {elementOffset(found.value, index), kNoOffset, true};
      node = &(*node)[index];
    } else {
      break;
    }
    at = end;
  }
  found.whole = at >= pointer.size();
  return found;
}

SourceLocation JsonDocument::locationOf(uint32_t offset) const {
  if (text_.empty()) return {file_, 1, 1};
  offset = std::min<uint32_t>(offset, static_cast<uint32_t>(text_.size() - 1));
  const size_t block = offset / 4096;
  uint32_t line = blockLines_[block], lineStart = blockLineStart_[block];
  for (size_t i = block * 4096; i < offset; ++i)
    if (text_[i] == '\n') {
      ++line;
      lineStart = static_cast<uint32_t>(i + 1);
    }
  return {file_, static_cast<int>(line + 1), static_cast<int>(offset - lineStart + 1)};
}

SourceLocation JsonDocument::valueAt(const std::string& pointer) const { return locationOf(find(pointer).value); }

SourceLocation JsonDocument::keyAt(const std::string& pointer) const {
  const Found found = find(pointer);
  return locationOf(found.whole && found.key != kNoOffset ? found.key : found.value);
}

size_t skipJsonSpace(const std::string& t, size_t i) {
  while (i < t.size() && (t[i] == ' ' || t[i] == '\t' || t[i] == '\n' || t[i] == '\r')) ++i;
  return i;
}

size_t skipJsonValue(const std::string& t, size_t i) {
  int depth = 0;
  do {
    const char c = t[i];
    if (c == '"') {
      for (++i; i < t.size() && t[i] != '"';) i += t[i] == '\\' ? 2 : 1;
      ++i;
    } else if (c == '{' || c == '[') {
      ++depth, ++i;
    } else if (c == '}' || c == ']') {
      --depth, ++i;
    } else if (depth == 0) {
      while (i < t.size() && std::string_view(",]} \t\r\n").find(t[i]) == std::string_view::npos) ++i;
    } else {
      ++i;
    }
  } while (depth > 0 && i < t.size());
  return i;
}

}  // namespace mb
