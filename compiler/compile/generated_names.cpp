#include "compile/generated_names.hpp"

#include <cctype>
#include <functional>
#include <mutex>
#include <optional>
#include <set>

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
using Generated = std::map<std::string, GeneratedName>;

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The material as the emitter would see it with one user parameter, the placeholder: every
// active model input a run-time input (so each has its p_ local), an empty surface(), and
// each role the material left unbound bound to its default or its slot's first brick.
MaterialDesc placeholderMaterial(const ShaderLibrary& lib, const MaterialDesc& material) {
  MaterialDesc m;
  m.name = "mb_placeholder";  // the same text, hence the same cache entries, for every material
  m.model = material.model;
  m.features = material.features;
  m.bricks = material.bricks;
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

// Identifiers of one line of code (no comments), each with where it starts and ends. Numbers,
// suffixes and exponents included, are skipped whole.
void forEachIdentifier(const std::string& code, const std::function<void(const std::string&, size_t, size_t)>& f) {
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
    f(code.substr(start, i - start), start, i);
  }
}

// How one occurrence in the emitter's own code uses a name.
struct Occurrence {
  bool member = false;     // after a '.': a member or a swizzle, never a name of the scope
  bool localDecl = false;  // `Type name` then '=', ';', ',', ')' or '[' inside a function
};

Occurrence classify(const std::string& line, size_t start, size_t end, bool inFunction) {
  Occurrence o;
  size_t before = line.find_last_not_of(" \t", start == 0 ? std::string::npos : start - 1);
  if (start > 0 && before != std::string::npos && line[before] == '.') o.member = true;
  size_t after = line.find_first_not_of(" \t", end);
  const char next = after == std::string::npos ? '\0' : line[after];
  if (inFunction && start > 0 && before != std::string::npos && isIdentChar(line[before]) &&
      std::string("=;,)[").find(next) != std::string::npos && next != '\0') {
    size_t typeStart = before + 1;
    while (typeStart > 0 && isIdentChar(line[typeStart - 1])) --typeStart;
    o.localDecl = line.compare(typeStart, before + 1 - typeStart, "return") != 0;
  }
  return o;
}

std::string withoutComment(const std::string& line) {
  size_t at = line.find("//");
  return at == std::string::npos ? line : line.substr(0, at);
}

// What the text scan found: every name with what it is, and which names the emitter's own code
// declares as a local or parameter of a generated function, and which it uses otherwise (a
// call, a global, a macro).
struct TextNames {
  Names names;
  std::set<std::string> locals;
  std::set<std::string> nonLocal;
};

// The text part: macros of every line, and the identifiers of the lines whose #line file is
// the generated file itself (`ownFile`), named after the generated function they are in.
void scanText(const std::string& glsl, const std::string& ownFile, TextNames& out) {
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
      std::vector<std::string> words;
      forEachIdentifier(line.substr(first + 1), [&](const std::string& w, size_t, size_t) { words.push_back(w); });
      if (words.size() >= 2 && words[0] == "define") {
        out.names.emplace(words[1], "a macro of " + (file == ownFile ? std::string("the generated code") : file));
        out.nonLocal.insert(words[1]);
      }
      if (!words.empty() && words[0] == "line") {
        size_t quote = line.find('"');
        if (quote != std::string::npos) file = line.substr(quote + 1, line.rfind('"') - quote - 1);
      }
      continue;
    }
    if (file != ownFile) continue;
    // The emitter writes each function's signature on one line, with its '{' (and the whole
    // body, for the one-line wrappers): its parameters and locals are the function's.
    size_t paren = line.find('(');
    size_t brace = line.find('{');
    if (depth == 0 && paren != std::string::npos && brace != std::string::npos && paren < brace &&
        line.compare(first, 6, "layout") != 0 && line.compare(first, 6, "struct") != 0) {
      size_t nameEnd = line.find_last_not_of(" \t", paren - 1) + 1;
      size_t nameStart = nameEnd;
      while (nameStart > 0 && isIdentChar(line[nameStart - 1])) --nameStart;
      function = line.substr(nameStart, nameEnd - nameStart);
      out.nonLocal.insert(function);
    }
    const std::string what =
        function.empty() ? "declared by the generated code" : "used in the generated " + function + "()";
    forEachIdentifier(line, [&](const std::string& w, size_t from, size_t to) {
      Occurrence o = classify(line, from, to, !function.empty());
      if (o.member) return;
      out.names.emplace(w, what);
      if (o.localDecl)
        out.locals.insert(w);
      else if (function.empty() || line.find_first_not_of(" \t", to) == line.find('(', to))
        out.nonLocal.insert(w);  // a global declaration, or a call
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

Generated derive(const ShaderLibrary& lib, const ShadingModel* model, const MaterialDesc& material) {
  TextNames text;
  const MaterialDesc placeholder = placeholderMaterial(lib, material);
  Names declared;
  bool first = true;
  // What differs between the variants: each environment mode brings its own inputs and
  // library code, fp16 its own brick variants and macros (its other identifiers are types);
  // the engine kernel, its fragment shader and the bench probe add their own wrapper lines,
  // and the fragment shader the frame block. glslang parses the fp32 probes and one fragment
  // shader: fp16 differs there only in types and in brick variants, which wrapper code never
  // calls by name (the skeleton calls MB_SLOT_<role>, a macro the text scan finds).
  for (Permutation perm : validationPermutationsFor(placeholder, lib)) {
    for (Precision precision : allPrecisions()) {
      perm.precision = precision;
      const bool fp32 = precision == Precision::Fp32;
      tryEmit([&] {
        EmittedShader probe = emitPermutation(lib, perm);
        scanText(probe.glsl, probe.fileName, text);
        if (fp32) addDeclarations(probe, ShaderStage::Compute, declared);
      });
      if (!fp32) continue;
      tryEmit([&] {
        EmittedShader engine = emitPermutation(lib, perm, false, EmitMode::Engine);
        scanText(engine.glsl, engine.fileName, text);
        EmittedShader fragment = fragmentShaderOf(lib, perm, engine, false);
        scanText(fragment.glsl, fragment.fileName, text);
        if (first) addDeclarations(fragment, ShaderStage::Fragment, declared);
      });
      if (first)
        tryEmit([&] {
          EmittedShader bench = emitPermutationBenchProbe(lib, perm, {1, false});
          scanText(bench.glsl, bench.fileName, text);
        });
      first = false;
    }
  }
  Generated out;
  for (const auto& [name, what] : text.names)
    out[name] = {what, text.locals.count(name) && !text.nonLocal.count(name) && !declared.count(name)};
  for (const auto& [name, what] : declared) out.emplace(name, GeneratedName{what, false});
  // A parameter X is the probe's local p_X and the bench probe's q_X.
  Generated prefixed;
  for (const auto& [name, g] : out)
    if (name.size() > 2 && (name.rfind("p_", 0) == 0 || name.rfind("q_", 0) == 0) && isIdentStart(name[2]))
      prefixed.emplace(name.substr(2), GeneratedName{"the name of the generated probe's local '" + name + "'", true});
  out.insert(prefixed.begin(), prefixed.end());
  for (const std::string& name : {kPlaceholder, "p_" + kPlaceholder, "q_" + kPlaceholder}) out.erase(name);
  for (const auto& in : model->inputs) out.erase(in.name);
  return out;
}

}  // namespace

std::map<std::string, GeneratedName> generatedIdentifiers(const ShaderLibrary& lib, const MaterialDesc& material) {
  const ShadingModel* model = lib.findModel(material.model);
  if (!model) return {};
  // What is emitted depends on the library and the material's model, features and bricks only.
  std::string key = lib.root().string() + '\n' + material.model + '\n';
  for (const auto& f : material.features) key += f + ',';
  for (const auto& [role, brick] : material.bricks) key += '\n' + role + '=' + brick;
  static std::mutex mutex;
  static std::map<std::string, Generated> cache;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(key); it != cache.end()) return it->second;
  }
  Generated names = derive(lib, model, material);
  std::lock_guard<std::mutex> lock(mutex);
  return cache.emplace(key, std::move(names)).first->second;
}

// The resolver (load/) asks for these names through load/generated_names_source.hpp.
[[maybe_unused]] static const bool registeredAsSource = (setGeneratedNamesSource(&generatedIdentifiers), true);

}  // namespace mb

// mb_compiler's link options name this symbol as undefined, so the linker takes this object (and
// the registration above) into every program, also where nothing calls generatedIdentifiers.
extern "C" const int mb_generated_names_source_linked = 1;
