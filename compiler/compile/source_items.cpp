#include "compile/source_items.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace mb {
namespace {

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\n") - b + 1);
}

bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Splits a parameter list at the commas outside (), <> and [] (MSL's
// spvUnsafeArray<float3, 9> is one type).
std::vector<std::string> splitParams(const std::string& list) {
  std::vector<std::string> out;
  std::string cur;
  int depth = 0;
  for (char c : list) {
    if (c == '(' || c == '<' || c == '[') ++depth;
    if (c == ')' || c == '>' || c == ']') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!trim(cur).empty()) out.push_back(trim(cur));
  return out;
}

}  // namespace

std::vector<SourceItem> topLevelItems(const std::string& source) {
  std::vector<SourceItem> items;
  std::istringstream in(source);
  std::string cur;
  int depth = 0;
  for (std::string line; std::getline(in, line);) {
    const std::string t = trim(line);
    if (depth == 0 && cur.empty() && t.empty()) continue;
    if (depth == 0 && cur.empty() && t[0] == '#') {
      items.push_back({line + "\n"});
      continue;
    }
    cur += line + "\n";
    for (char c : line) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    // An item ends at depth 0 with ';' (declaration, struct) or '}' (function body).
    if (depth == 0 && !t.empty() && (t.back() == ';' || t.back() == '}')) {
      items.push_back({cur});
      cur.clear();
    }
  }
  if (!trim(cur).empty()) items.push_back({cur});
  return items;
}

std::optional<FunctionSignature> findFunction(const std::string& text, const std::string& name) {
  for (size_t at = text.find(name + "("); at != std::string::npos; at = text.find(name + "(", at + 1)) {
    // The name stands alone, after its return type on the same line.
    if (at == 0 || text[at - 1] != ' ') continue;
    const size_t lineStart = text.rfind('\n', at) == std::string::npos ? 0 : text.rfind('\n', at) + 1;
    const std::string returnType = trim(text.substr(lineStart, at - lineStart));
    if (returnType.empty() || !std::all_of(returnType.begin(), returnType.end(), isIdentChar)) continue;
    const size_t open = at + name.size();
    int depth = 0;
    size_t close = open;
    for (; close < text.size(); ++close) {
      depth += text[close] == '(' ? 1 : text[close] == ')' ? -1 : 0;
      if (depth == 0) break;
    }
    if (close >= text.size()) return std::nullopt;
    const size_t next = text.find_first_not_of(" \t\n", close + 1);
    if (next == std::string::npos || (text[next] != '{' && text[next] != ';')) continue;
    FunctionSignature sig;
    sig.returnType = returnType;
    sig.name = name;
    sig.text = text.substr(lineStart, close + 1 - lineStart);
    sig.defined = text[next] == '{';
    for (const auto& p : splitParams(text.substr(open + 1, close - open - 1))) {
      size_t end = p.size();
      while (end > 0 && isIdentChar(p[end - 1])) --end;
      if (p == "void") continue;
      sig.params.push_back({trim(p.substr(0, end)), p.substr(end)});
    }
    return sig;
  }
  return std::nullopt;
}

std::string bareType(const std::string& paramType) {
  std::istringstream in(paramType);
  std::string word, type;
  while (in >> word)
    if (word != "thread" && word != "const" && word != "in" && word != "out" && word != "inout") type = word;
  while (!type.empty() && type.back() == '&') type.pop_back();
  return type;
}

}  // namespace mb
