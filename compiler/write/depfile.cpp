#include "write/depfile.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <sstream>

namespace mb {
namespace {

namespace fs = std::filesystem;

std::string absolutePath(const fs::path& p) { return fs::absolute(p).lexically_normal().generic_string(); }

std::string escaped(const std::string& path);

}  // namespace

// Files named by `#line N "file"` directives: shader library files appear as
// "shaderlib/<relative>" (ShaderLibrary::displayPath), user surface code as its own path.
void addGlslInputs(const ShaderLibrary& lib, const std::string& glsl, std::set<std::string>& out) {
  std::istringstream in(glsl);
  const std::string libPrefix = ShaderLibrary::displayPath("");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#line ", 0) != 0) continue;
    size_t open = line.find('"'), close = line.rfind('"');
    if (open == std::string::npos || close <= open) continue;
    std::string file = line.substr(open + 1, close - open - 1);
    if (file.rfind(libPrefix, 0) == 0)
      out.insert(absolutePath(lib.root() / file.substr(libPrefix.size())));
    else if (fs::exists(file))  // the generated file's own name is not a file on disk
      out.insert(absolutePath(file));
  }
}

namespace {

// What Ninja's depfile parser (src/depfile_parser.in.cc, which follows GCC's -MD output) reads
// back as the same path, or nullopt for a path it cannot carry: a newline or carriage return
// ends a rule, a tab or another control character is whitespace or is kept with its escape,
// a path ending in a backslash would escape the separator that follows it, and one ending in
// ':' would end a target (Ninja keeps the backslash of "\\:" before whitespace).
//   space: 2N+1 backslashes and a space are N backslashes and a space (GCC doubles the
//          backslashes before a space and adds one);
//   '#', ':': a backslash before it is dropped, earlier ones kept (one backslash added; ':'
//          followed by whitespace would end a target);
//   '$': "$$" (Make's and Ninja's variable character).
std::optional<std::string> escapedForDepfile(const std::string& path) {
  if (path.empty() || path.back() == '\\' || path.back() == ':') return std::nullopt;
  std::string e;
  size_t backslashes = 0;
  for (char c : path) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return std::nullopt;
    if (c == ' ') e.append(backslashes + 1, '\\');
    if (c == '#' || c == ':') e += '\\';
    if (c == '$') e += '$';
    e += c;
    backslashes = c == '\\' ? backslashes + 1 : 0;
  }
  return e;
}

std::string escaped(const std::string& path) {
  if (auto e = escapedForDepfile(path)) return *e;
  throw DiagnosticError({{Severity::Error, "E-DEPFILE-PATH", {printablePath(path), 0, 0}, depfileRefusal(path), ""}});
}

}  // namespace

std::vector<std::string> compileInputs(const ShaderLibrary& lib, const std::vector<Permutation>& perms,
                                       const std::set<std::string>& glslInputs, const std::vector<std::string>& extra) {
  std::set<std::string> files = glslInputs;
  for (const auto& e : extra)
    if (!e.empty()) files.insert(absolutePath(e));
  files.insert(absolutePath(lib.root() / "manifest.json"));
  // Every permutation's fragment shader includes the frame block (emit/fragment_shader.cpp).
  files.insert(absolutePath(lib.root() / "common" / "engine_frame.glsl"));
  // ShaderLibrary::load reads every slot's slot.json, and the glTF defaults it declares.
  if (!lib.gltfDefaults().file.empty()) files.insert(absolutePath(lib.root() / lib.gltfDefaults().file));
  for (const auto& entry : fs::directory_iterator(lib.root()))
    if (entry.is_directory() && fs::exists(entry.path() / "slot.json"))
      files.insert(absolutePath(entry.path() / "slot.json"));
  for (const auto& p : perms) {
    const MaterialDesc& m = *p.material;
    if (!m.sourceFile.empty() && fs::exists(m.sourceFile)) files.insert(absolutePath(m.sourceFile));
    for (const auto& inc : m.includedFiles) files.insert(absolutePath(inc));
    if (m.surface.present() && fs::exists(m.surface.where.file)) files.insert(absolutePath(m.surface.where.file));
    files.insert(absolutePath(lib.root() / "models" / (m.model + ".json")));
  }
  return {files.begin(), files.end()};
}

std::string printablePath(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      static const char* const kHex = "0123456789abcdef";
      out += std::string("\\x") + kHex[(c >> 4) & 0xf] + kHex[c & 0xf];
    } else {
      out += c;
    }
  }
  return out;
}

std::string depfileTarget(const std::string& out) { return absolutePath(fs::path(out) / "manifest.json"); }

std::string depfileRefusal(const std::string& path) {
  if (escapedForDepfile(path)) return {};
  return "the depfile cannot name this path: Make and Ninja read no escape for a newline, tab or other control "
         "character, nor for a path ending in a backslash or ':' (rename the file or compile without --depfile)";
}

void checkDepfilePaths(const std::string& target, const std::vector<std::string>& deps) {
  escaped(target);
  for (const auto& d : deps) escaped(d);
}

std::string makeDepfile(const std::string& target, const std::vector<std::string>& deps) {
  std::string out = escaped(target) + ":";
  for (const auto& d : deps) out += " \\\n  " + escaped(d);
  return out + "\n";
}

}  // namespace mb
