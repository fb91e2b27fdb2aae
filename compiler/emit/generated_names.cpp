#include "emit/generated_names.hpp"

#include <cctype>
#include <functional>
#include <mutex>
#include <optional>

#include "compile/glsl_declarations.hpp"
#include "emit/bench_probe.hpp"
#include "emit/emitter.hpp"
#include "emit/fragment_shader.hpp"
#include "permute/axes.hpp"

namespace mb {
namespace {

// A name no user can write (mb_ names are reserved from users), so whatever holds it in the
// emitted code is a user parameter's place.
const std::string kPlaceholder = "mb_user_parameter_placeholder";

using Names = std::map<std::string, std::string>;

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The material as the emitter would see it with one user parameter, the placeholder: every
// active model input a run-time input (so each has its p_ local), an empty surface(), and
// each role the material left unbound bound to its default or its slot's first brick.
MaterialDesc placeholderMaterial(const ShaderLibrary& lib, const MaterialDesc& material) {
  MaterialDesc m = material;
  m.params.clear();
  const ShadingModel* model = lib.findModel(material.model);
  for (const auto& in : model->inputs) {
    if (!in.feature.empty() && !m.has(in.feature)) continue;
    m.params.push_back({.name = in.name, .type = in.type, .value = in.defaultValue, .range = in.range, .where = {}});
  }
  m.params.push_back({.name = kPlaceholder, .value = {0.5}, .range = {0.0, 1.0}, .user = true, .where = {}});
  m.surface.glsl = "void surface(inout MaterialInputs m, MaterialParams p) {}\n";
  m.surface.where = {"<surface code>", 1, 1};
  for (const auto& role : model->roles) {
    if (m.bricks.count(role.role) || (!role.feature.empty() && !m.has(role.feature))) continue;
    std::vector<std::string> bricks = lib.bricksOfSlot(role.slot);
    if (!role.defaultBrick.empty())
      m.bricks[role.role] = role.defaultBrick;
    else if (!bricks.empty())
      m.bricks[role.role] = bricks.front();
  }
  return m;
}

// Identifiers of one line of code (no comments), each with whether a '.' precedes it (a
// member or a swizzle: never a name of the scope). Numbers, suffixes and exponents included,
// are skipped whole.
void forEachIdentifier(const std::string& code, const std::function<void(const std::string&, bool)>& f) {
  for (size_t i = 0; i < code.size();) {
    if (std::isdigit(static_cast<unsigned char>(code[i]))) {
      while (i < code.size() && (isIdentChar(code[i]) || code[i] == '.')) ++i;
      continue;
    }
    if (!isIdentStart(code[i])) {
      ++i;
      continue;
    }
    size_t start = i;
    while (i < code.size() && isIdentChar(code[i])) ++i;
    size_t before = start;
    while (before > 0 && (code[before - 1] == ' ' || code[before - 1] == '\t')) --before;
    f(code.substr(start, i - start), before > 0 && code[before - 1] == '.');
  }
}

std::string withoutComment(const std::string& line) {
  size_t at = line.find("//");
  return at == std::string::npos ? line : line.substr(0, at);
}

// The text part: macros of every line, and the identifiers of the lines whose #line file is
// the generated file itself (`ownFile`), named after the generated function they are in.
void scanText(const std::string& glsl, const std::string& ownFile, Names& out) {
  std::string file = ownFile;
  std::string function;
  int depth = 0;
  size_t start = 0;
  while (start < glsl.size()) {
    size_t end = glsl.find('\n', start);
    if (end == std::string::npos) end = glsl.size();
    const std::string line = withoutComment(glsl.substr(start, end - start));
    start = end + 1;
    size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line[first] == '#') {
      std::string directive;
      std::vector<std::string> words;
      forEachIdentifier(line.substr(first + 1), [&](const std::string& w, bool) { words.push_back(w); });
      if (words.size() >= 2 && words[0] == "define")
        out.emplace(words[1], "a macro of " + (file == ownFile ? std::string("the generated code") : file));
      if (!words.empty() && words[0] == "line") {
        size_t quote = line.find('"');
        if (quote != std::string::npos) file = line.substr(quote + 1, line.rfind('"') - quote - 1);
      }
      continue;
    }
    if (file != ownFile) continue;
    // The emitter writes each function's signature on one line ending in '{'.
    size_t paren = line.find('(');
    size_t last = line.find_last_not_of(" \t");
    if (depth == 0 && paren != std::string::npos && last != std::string::npos && line[last] == '{' &&
        line.compare(first, 6, "layout") != 0 && line.compare(first, 6, "struct") != 0) {
      size_t nameEnd = line.find_last_not_of(" \t", paren - 1) + 1;
      size_t nameStart = nameEnd;
      while (nameStart > 0 && isIdentChar(line[nameStart - 1])) --nameStart;
      function = line.substr(nameStart, nameEnd - nameStart);
    }
    const std::string what =
        depth > 0 && !function.empty() ? "used in the generated " + function + "()" : "declared by the generated code";
    forEachIdentifier(line, [&](const std::string& w, bool member) {
      if (!member) out.emplace(w, what);
    });
    for (char c : line) depth += c == '{' ? 1 : c == '}' ? -1 : 0;
    if (depth <= 0) {
      depth = 0;
      function.clear();
    }
  }
}

// glslang's global declarations of `glsl`, cached by text: the same material in the same
// library emits the same text, and every material of a model shares most of it.
std::optional<Names> cachedDeclarations(const std::string& glsl, ShaderStage stage) {
  static std::mutex mutex;
  static std::map<std::pair<size_t, size_t>, std::optional<Names>> cache;
  const std::pair<size_t, size_t> key{std::hash<std::string>{}(glsl), glsl.size()};
  {
    std::lock_guard<std::mutex> lock(mutex);
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
  }
  std::optional<Names> names = glslGlobalDeclarations(glsl, stage);
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, std::move(names)).first->second;
}

void addDeclarations(const EmittedShader& shader, ShaderStage stage, Names& out) {
  if (auto names = cachedDeclarations(shader.glsl, stage)) out.insert(names->begin(), names->end());
}

// Runs one emission; one the permutation's rules refuse (a brick rule, a light the model
// lacks) adds nothing.
template <typename Emit>
void tryEmit(Emit&& emit) {
  try {
    emit();
  } catch (const DiagnosticError&) {
  } catch (const std::exception&) {
  }
}

}  // namespace

std::map<std::string, std::string> generatedIdentifiers(const ShaderLibrary& lib, const MaterialDesc& material) {
  Names out;
  const ShadingModel* model = lib.findModel(material.model);
  if (!model) return out;
  const MaterialDesc placeholder = placeholderMaterial(lib, material);
  Names declared;
  bool fragmentParsed = false;
  for (Permutation perm : validationPermutationsFor(placeholder, lib)) {
    for (const std::string& precision : allPrecisions()) {
      perm.precision = precision;
      tryEmit([&] {
        EmittedShader probe = emitPermutation(lib, perm);
        scanText(probe.glsl, probe.fileName, out);
        addDeclarations(probe, ShaderStage::Compute, declared);
      });
      tryEmit([&] {
        EmittedShader engine = emitPermutation(lib, perm, false, EmitMode::Engine);
        scanText(engine.glsl, engine.fileName, out);
        EmittedShader fragment = fragmentShaderOf(lib, perm, engine, false);
        scanText(fragment.glsl, fragment.fileName, out);
        // Its library part is the kernel's and the frame block's: one parse finds the latter.
        if (!fragmentParsed) addDeclarations(fragment, ShaderStage::Fragment, declared);
        fragmentParsed = true;
      });
      tryEmit([&] {
        EmittedShader bench = emitPermutationBenchProbe(lib, perm, {1, false});
        scanText(bench.glsl, bench.fileName, out);
      });
    }
  }
  out.insert(declared.begin(), declared.end());
  // A parameter X is the probe's local p_X and the bench probe's q_X.
  Names prefixed;
  for (const auto& [name, what] : out)
    if (name.size() > 2 && (name.rfind("p_", 0) == 0 || name.rfind("q_", 0) == 0) && isIdentStart(name[2]))
      prefixed.emplace(name.substr(2), "the name of the generated probe's local '" + name + "'");
  out.insert(prefixed.begin(), prefixed.end());
  for (const std::string& name : {kPlaceholder, "p_" + kPlaceholder, "q_" + kPlaceholder}) out.erase(name);
  for (const auto& in : model->inputs) out.erase(in.name);
  return out;
}

}  // namespace mb
