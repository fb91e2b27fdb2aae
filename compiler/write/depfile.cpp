#include "write/depfile.hpp"

#include <filesystem>
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

std::string escaped(const std::string& path) {
  std::string e;
  for (char c : path) {
    if (c == ' ' || c == '#') e += '\\';
    if (c == '$') e += '$';
    e += c;
  }
  return e;
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
  // ShaderLibrary::load reads every slot's slot.json.
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

std::string makeDepfile(const std::string& target, const std::vector<std::string>& deps) {
  std::string out = escaped(target) + ":";
  for (const auto& d : deps) out += " \\\n  " + escaped(d);
  return out + "\n";
}

}  // namespace mb
