// The macro form (.mat): seed 000's "More PBR" encodes a material's skeleton in #define
// MACROs, like a Unity surface shader. Grammar and every directive: docs/macro-form.md.
// This file reads directives and includes into a MaterialSource; resolveMaterial (shared with
// JSON and glTF) checks what they mean. Every line's problem is reported, then the next line
// is read, so one run shows every mistake.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "core/json_document.hpp"
#include "load/macro_lexer.hpp"
#include "load/material_desc.hpp"
#include "load/material_resolve.hpp"
#include "load/project_files.hpp"

namespace mb {

namespace {

namespace fs = std::filesystem;
using Kind = MacroToken::Kind;

// Deeper than this is a mistake, not a design (cycles are caught separately).
constexpr size_t kMaxIncludeDepth = 16;

const std::vector<std::string>& directiveNames() {
  static const std::vector<std::string> names = {"MATERIAL",          "MODEL",        "DESCRIPTION",
                                                 "FEATURE_<feature>", "BRICK_<role>", "LIGHT_METHOD_<light>",
                                                 "PARAM_<name>",      "CONST_<name>"};
  return names;
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

std::string at(const SourceLocation& l) {
  return l.file + ":" + std::to_string(l.line) + ":" + std::to_string(l.column);
}

// One physical line being read: where it is, and its tokens after the macro name.
struct Line {
  const std::string& file;
  int number;
  std::vector<MacroToken> tokens;
  size_t next = 0;

  SourceLocation where(int column) const { return SourceLocation(file, number, column); }
  const MacroToken& peek() const { return tokens[std::min(next, tokens.size() - 1)]; }
  const MacroToken& take() {
    const MacroToken& t = peek();
    if (next < tokens.size() - 1) ++next;
    return t;
  }
};

class MacroReader {
 public:
  MacroReader(const std::string& topFile, DiagnosticSink& sink) : project_(topFile), sink_(sink) {
    src_.file = topFile;
    src_.form = "macro";
  }

  MaterialSource run(const std::string& text) {
    stack_.push_back({canonicalKey(src_.file), src_.file});
    included_.insert(stack_.back().first);
    readFile(text, src_.file, true);
    SourceLocation top(src_.file, 1, 1);
    if (binary_) return src_;  // nothing more to say about a file that is not text
    if (src_.name.where.file.empty() && !defined_.count("MATERIAL"))
      sink_.error("E-MISSING-FIELD", top, "the material has no name: expected '#define MATERIAL <name>'");
    if (src_.model.where.file.empty() && !defined_.count("MODEL"))
      sink_.error("E-MISSING-FIELD", top, "the material has no model: expected '#define MODEL <model>'");
    src_.bricksWhere = src_.model.where.file.empty() ? top : src_.model.where;
    return src_;
  }

 private:
  static std::string canonicalKey(const std::string& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::path(path).lexically_normal().string() : p.string();
  }

  void error(const SourceLocation& where, std::string code, std::string message, std::string suggestion = {}) {
    sink_.error(std::move(code), where, std::move(message), std::move(suggestion));
  }

  // Directives, comments and blank lines; in the top-level file the first other line starts
  // the surface code, which runs to the end of the file.
  void readFile(const std::string& text, const std::string& file, bool top) {
    if (size_t nul = text.find('\0'); nul != std::string::npos) {
      error(locationOfOffset(text, nul, file), "E-MACRO-SYNTAX",
            "binary data (a NUL byte): expected a text file of #define lines and GLSL");
      binary_ = binary_ || top;
      return;
    }
    size_t pos = 0;
    for (int number = 1; pos <= text.size(); ++number) {
      size_t end = text.find('\n', pos);
      if (end == std::string::npos) end = text.size();
      std::string line = text.substr(pos, end - pos);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      size_t first = line.find_first_not_of(" \t");
      bool blank = first == std::string::npos || line.compare(first, 2, "//") == 0;
      if (!blank && line[first] == '#') {
        hashLine(line, first, file, number);
      } else if (!blank && !missingHash(line, first, file, number)) {
        if (!top) {
          error(SourceLocation(file, number, static_cast<int>(first + 1)), "E-MACRO-SYNTAX",
                "expected a directive, a comment or a blank line: surface code belongs in the top-level "
                "material file, not in an included one");
          return;
        }
        src_.surface = {surfaceText(text, pos), SourceLocation(file, number, 1)};
        return;
      }
      pos = end + 1;
    }
  }

  // The rest of the file from `pos`, with CR LF line ends made LF.
  static std::string surfaceText(const std::string& text, size_t pos) {
    std::string out;
    out.reserve(text.size() - pos);
    for (size_t i = pos; i < text.size(); ++i)
      if (!(text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) out += text[i];
    return out;
  }

  // A directive that lost its '#' ("define MODEL standard", "MODEL standard") would otherwise
  // silently start the surface code.
  bool missingHash(const std::string& line, size_t first, const std::string& file, int number) {
    auto tokens = tokenizeDirective(line, first);
    const std::string& word = tokens.front().text;
    bool directive = tokens.front().kind == Kind::Identifier &&
                     (word == "define" || word == "include" || word == "MATERIAL" || word == "MODEL" ||
                      word == "DESCRIPTION" || startsWith(word, "FEATURE_") || startsWith(word, "BRICK_") ||
                      startsWith(word, "LIGHT_METHOD_") || startsWith(word, "PARAM_") || startsWith(word, "CONST_"));
    if (!directive) return false;
    error(SourceLocation(file, number, static_cast<int>(first + 1)), "E-MACRO-SYNTAX",
          "'" + word + "' without '#': expected '#" +
              (word == "define" || word == "include" ? word : "define " + word) + " ...'");
    return true;
  }

  void hashLine(const std::string& text, size_t hash, const std::string& file, int number) {
    Line line{file, number, tokenizeDirective(text, hash + 1)};
    const MacroToken& word = line.take();
    if (word.kind == Kind::Identifier && word.text == "define") return define(line, text);
    if (word.kind == Kind::Identifier && word.text == "include") return include(line);
    if (word.kind == Kind::Invalid) return error(line.where(word.column), "E-MACRO-SYNTAX", word.text);
    error(line.where(word.column), "E-UNKNOWN-DIRECTIVE",
          "unknown directive '#" + clipped(word.text) +
              "': expected #define or #include (GLSL preprocessor lines belong in the surface code, after "
              "its first line)",
          word.kind == Kind::Identifier ? suggest(word.text, {"define", "include"}) : "");
  }

  // Reports `t` as unexpected where `expected` should be; returns false for the caller's `return`.
  bool unexpected(const Line& line, const MacroToken& t, const std::string& expected) {
    if (t.kind == Kind::Invalid)
      error(line.where(t.column), "E-MACRO-SYNTAX", t.text);
    else
      error(line.where(t.column), "E-MACRO-SYNTAX", "expected " + expected + ", found " + describeToken(t));
    return false;
  }

  bool expectEnd(Line& line, const std::string& after) {
    const MacroToken& t = line.take();
    return t.kind == Kind::End || unexpected(line, t, "the end of the line after " + after);
  }

  // --- #define ----------------------------------------------------------------------------

  void define(Line& line, const std::string& text) {
    const MacroToken& name = line.take();
    if (name.kind != Kind::Identifier) {
      unexpected(line, name, "a macro name after #define (" + joined(directiveNames()) + ")");
      return;
    }
    // The body must be separated from the name: "#define MODEL(x)" is a function-like macro.
    size_t after = static_cast<size_t>(name.column - 1) + name.text.size();
    if (after < text.size() && text[after] == '(') {
      error(line.where(static_cast<int>(after + 1)), "E-MACRO-SYNTAX",
            "function-like macros are not directives: expected a space between '" + clipped(name.text) +
                "' and its value");
      return;
    }
    const std::string& n = name.text;
    SourceLocation where = line.where(name.column);
    if (n == "MATERIAL" || n == "MODEL") return single(line, n, where, n == "MATERIAL" ? src_.name : src_.model);
    if (n == "DESCRIPTION") return description(line, where);
    for (const char* prefix : {"FEATURE_", "BRICK_", "LIGHT_METHOD_", "PARAM_", "CONST_"}) {
      std::string p = prefix;
      if (!startsWith(n, p)) continue;
      SourceName rest{n.substr(p.size()), line.where(name.column + static_cast<int>(p.size()))};
      if (rest.value.empty()) {
        error(rest.where, "E-MACRO-SYNTAX", "expected a name after '" + p + "'");
        return;
      }
      if (p == "FEATURE_") return feature(line, rest, where);
      if (p == "BRICK_") return brick(line, rest, where);
      if (p == "LIGHT_METHOD_") return lightMethod(line, rest, where);
      return param(line, rest, p == "CONST_", where);
    }
    std::vector<std::string> candidates = {"MATERIAL", "MODEL", "DESCRIPTION"};
    // A misspelt prefix keeps its name: BRIK_fresnel -> BRICK_fresnel.
    size_t us = n.find('_');
    std::string tail = us == std::string::npos ? std::string() : n.substr(us + 1);
    for (const char* prefix : {"FEATURE_", "BRICK_", "PARAM_", "CONST_"}) candidates.push_back(prefix + tail);
    error(where, "E-UNKNOWN-DIRECTIVE",
          "unknown directive '" + clipped(n) + "': expected one of " + joined(directiveNames()),
          suggest(n, candidates));
  }

  static std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return s;
  }

  // True the first time `key` is defined; otherwise reports the redefinition.
  bool firstDefinition(const std::string& key, const std::string& what, const SourceLocation& where) {
    auto [it, fresh] = defined_.emplace(key, where);
    if (!fresh) error(where, "E-DUPLICATE-DEFINITION", what + " is defined twice (first at " + at(it->second) + ")");
    return fresh;
  }

  void single(Line& line, const std::string& macro, const SourceLocation& where, SourceName& into) {
    if (!firstDefinition(macro, "'" + macro + "'", where)) return;
    const MacroToken& value = line.take();
    if (value.kind != Kind::Identifier) {
      unexpected(line, value, macro == "MATERIAL" ? "a material name [A-Za-z_][A-Za-z0-9_]*" : "a model name");
      return;
    }
    if (!expectEnd(line, "the " + std::string(macro == "MATERIAL" ? "material" : "model") + " name")) return;
    into = {value.text, line.where(value.column)};
  }

  void description(Line& line, const SourceLocation& where) {
    if (!firstDefinition("DESCRIPTION", "'DESCRIPTION'", where)) return;
    const MacroToken& value = line.take();
    if (value.kind != Kind::String) {
      unexpected(line, value, "a \"quoted\" description");
      return;
    }
    if (expectEnd(line, "the description")) src_.description = value.text;
  }

  void feature(Line& line, const SourceName& name, const SourceLocation& where) {
    if (!firstDefinition("FEATURE_" + name.value, "feature '" + clipped(name.value) + "'", where)) return;
    if (expectEnd(line, "FEATURE_" + clipped(name.value) + " (a feature takes no value)"))
      src_.features.push_back(name);
  }

  void brick(Line& line, const SourceName& role, const SourceLocation& where) {
    if (!firstDefinition("BRICK_" + role.value, "the brick of role '" + clipped(role.value) + "'", where)) return;
    const MacroToken& id = line.take();
    if (id.kind != Kind::Identifier) {
      unexpected(line, id, "a brick id");
      return;
    }
    if (expectEnd(line, "the brick id")) src_.bricks.push_back({role, SourceName{id.text, line.where(id.column)}});
  }

  // LIGHT_METHOD_<light> <method>: the JSON form's "lightMethods" member.
  void lightMethod(Line& line, const SourceName& light, const SourceLocation& where) {
    if (!firstDefinition("LIGHT_METHOD_" + light.value, "the method of light '" + clipped(light.value) + "'", where))
      return;
    const MacroToken& method = line.take();
    if (method.kind != Kind::Identifier) {
      unexpected(line, method, "a light method name");
      return;
    }
    if (expectEnd(line, "the method name"))
      src_.lightMethods.push_back({light, SourceName{method.text, line.where(method.column)}});
  }

  // PARAM_<name> <value> [RANGE(lo, hi)], CONST_<name> <value> [RANGE(lo, hi)].
  void param(Line& line, const SourceName& name, bool constant, const SourceLocation& where) {
    if (!firstDefinition("param " + name.value, "parameter '" + clipped(name.value) + "'", where)) return;
    SourceParam sp;
    sp.name = name.value;
    sp.where = name.where;
    sp.constant = constant;
    if (!value(line, sp)) return;
    const MacroToken& t = line.take();
    if (t.kind == Kind::Identifier && t.text == "RANGE") {
      sp.rangeWhere = line.where(t.column);
      std::vector<double> bounds;
      if (!numberList(line, "RANGE", bounds, nullptr)) return;
      if (bounds.size() != 2) {
        error(sp.rangeWhere, "E-MACRO-SYNTAX",
              "RANGE takes two numbers (lo, hi), found " + std::to_string(bounds.size()));
        return;
      }
      sp.range = Range{bounds[0], bounds[1]};
      if (!expectEnd(line, "RANGE(lo, hi)")) return;
    } else if (t.kind != Kind::End) {
      error(
          line.where(t.column), "E-MACRO-SYNTAX",
          t.kind == Kind::Invalid ? t.text : "expected RANGE(lo, hi) or the end of the line, found " + describeToken(t),
          t.kind == Kind::Identifier ? suggest(t.text, {"RANGE"}) : "");
      return;
    }
    src_.params.push_back(std::move(sp));
  }

  // A number (a float), or float(x), vec2(x, y), vec3(x, y, z); vecN(x) repeats x, as GLSL.
  bool value(Line& line, SourceParam& sp) {
    const MacroToken& t = line.take();
    sp.valueWhere = sp.typeWhere = line.where(t.column);
    if (t.kind == Kind::Number) {
      sp.type = "float";
      sp.value = {t.number};
      sp.componentWhere = {sp.valueWhere};
      return true;
    }
    if (t.kind != Kind::Identifier || line.peek().kind != Kind::LParen)
      return unexpected(line, t, "a value: a number, float(x), vec2(x, y) or vec3(x, y, z)");
    const std::vector<std::string> types = {"float", "vec2", "vec3"};
    if (std::find(types.begin(), types.end(), t.text) == types.end()) {
      error(sp.typeWhere, "E-PARAM-TYPE",
            "unknown parameter type '" + clipped(t.text) + "': expected float, vec2 or vec3", suggest(t.text, types));
      return false;
    }
    std::string type = t.text;
    if (!numberList(line, type, sp.value, &sp.componentWhere)) return false;
    size_t n = type == "float" ? 1 : type == "vec2" ? 2 : 3;
    if (sp.value.size() == 1 && n > 1) {
      sp.value.assign(n, sp.value[0]);
      sp.componentWhere.assign(n, sp.componentWhere[0]);
    }
    if (sp.value.size() != n) {
      error(sp.typeWhere, "E-PARAM-TYPE",
            type + "(...) takes " + (n == 1 ? "1 number" : "1 or " + std::to_string(n) + " numbers") + ", found " +
                std::to_string(sp.value.size()));
      return false;
    }
    sp.type = type;
    return true;
  }

  // "(" number {"," number} ")" after `what`.
  bool numberList(Line& line, const std::string& what, std::vector<double>& out, std::vector<SourceLocation>* where) {
    const MacroToken& open = line.take();
    if (open.kind != Kind::LParen) return unexpected(line, open, "'(' after " + what);
    while (true) {
      const MacroToken& x = line.take();
      if (x.kind != Kind::Number) return unexpected(line, x, "a number in " + what + "(...)");
      out.push_back(x.number);
      if (where) where->push_back(line.where(x.column));
      const MacroToken& sep = line.take();
      if (sep.kind == Kind::RParen) return true;
      if (sep.kind != Kind::Comma) return unexpected(line, sep, "',' or ')' in " + what + "(...)");
    }
  }

  // --- #include ---------------------------------------------------------------------------

  void include(Line& line) {
    const MacroToken& path = line.take();
    if (path.kind != Kind::String) {
      unexpected(line, path, "a \"quoted\" path after #include");
      return;
    }
    SourceLocation where = line.where(path.column);
    if (!expectEnd(line, "the include path")) return;
    // An include that is refused or unreadable may have held brick choices: missing roles are
    // then not reported, only the include's own error (as for other unreadable choices).
    auto resolved = project_.resolve(path.text, line.file, where, sink_);
    if (!resolved) {
      src_.bricksIncomplete = true;
      return;
    }
    std::string key = canonicalKey(*resolved);
    for (size_t i = 0; i < stack_.size(); ++i) {
      if (stack_[i].first != key) continue;
      std::string cycle;
      for (size_t j = i; j < stack_.size(); ++j) cycle += stack_[j].second + " -> ";
      error(where, "E-INCLUDE-CYCLE", "include cycle: " + cycle + *resolved);
      return;
    }
    if (!included_.insert(key).second) return;  // each file is read once, as with #pragma once
    if (stack_.size() >= kMaxIncludeDepth) {
      error(where, "E-INCLUDE-DEPTH", "includes nested deeper than " + std::to_string(kMaxIncludeDepth) + " files");
      src_.bricksIncomplete = true;
      return;
    }
    auto text = readTextFile(*resolved, where, input_kind::kMacroInclude, sink_);
    if (!text) {
      src_.bricksIncomplete = true;
      return;
    }
    src_.includedFiles.push_back(*resolved);
    stack_.push_back({key, *resolved});
    readFile(*text, *resolved, false);
    stack_.pop_back();
  }

  ProjectFiles project_;
  DiagnosticSink& sink_;
  MaterialSource src_;
  std::map<std::string, SourceLocation> defined_;           // macro (or parameter) -> first definition
  std::vector<std::pair<std::string, std::string>> stack_;  // open files: canonical key, shown path
  std::set<std::string> included_;
  bool binary_ = false;  // the top-level file is not text
};

}  // namespace

MaterialDesc parseMaterialMacro(const std::string& text, const std::string& file, const ShaderLibrary& lib) {
  DiagnosticSink sink;
  return finishMaterial(MacroReader(file, sink).run(text), lib, sink);
}

MaterialDesc loadMaterialMacro(const std::string& path, const ShaderLibrary& lib) {
  return parseMaterialMacro(readMaterialFile(path, input_kind::kMacroMaterial), path, lib);
}

}  // namespace mb
