#include "write/output_paths.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/diagnostics.hpp"

namespace mb {
namespace fs = std::filesystem;

namespace {

struct FileId {
  dev_t dev;
  ino_t ino;
  bool operator==(const FileId&) const = default;
};

std::optional<FileId> fileId(const fs::path& p) {
  struct stat st {};
  if (::stat(p.c_str(), &st) != 0) return std::nullopt;
  return FileId{st.st_dev, st.st_ino};
}

// The identities of `p` (when it exists) and of every existing directory above it, nearest
// first. weakly_canonical resolves symlinks and ".." in the part that exists, so walking up
// the result's parents follows the directories the kernel would.
std::vector<FileId> ancestry(const fs::path& p, bool& selfExists) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(p), ec);
  if (ec) resolved = fs::absolute(p).lexically_normal();
  std::vector<FileId> chain;
  selfExists = false;
  bool first = true;
  for (fs::path q = resolved;; q = q.parent_path()) {
    if (auto id = fileId(q)) {
      chain.push_back(*id);
      if (first) selfExists = true;
    }
    first = false;
    if (q == q.root_path() || q.parent_path() == q) break;
  }
  return chain;
}

// For a protected path that does not exist yet: compare the resolved paths component-wise.
std::string lexicalRelation(const fs::path& output, const fs::path& input) {
  auto resolved = [](const fs::path& p) {
    std::error_code ec;
    std::string s = fs::weakly_canonical(fs::absolute(p), ec).lexically_normal().generic_string();
    while (s.size() > 1 && s.back() == '/') s.pop_back();
    return s;
  };
  const std::string out = resolved(output), in = resolved(input);
  auto above = [](const std::string& a, const std::string& b) {  // a is a directory above b
    return b.size() > a.size() && b.compare(0, a.size(), a) == 0 && (a == "/" || b[a.size()] == '/');
  };
  if (out == in) return "is";
  if (above(out, in)) return "contains";
  if (above(in, out)) return "lies inside";
  return "";
}

bool contains(const std::vector<FileId>& chain, const FileId& id) {
  return std::find(chain.begin(), chain.end(), id) != chain.end();
}

[[noreturn]] void fail(const std::string& code, const fs::path& where, const std::string& message,
                       const std::string& suggestion = {}) {
  throw DiagnosticError({{Severity::Error, code, {where.string(), 0, 0}, message, suggestion}});
}

// "a.json, README.md, src/ and 5 more"
std::string someEntries(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    names.push_back(it->path().filename().string() + (it->is_directory(ec) ? "/" : ""));
  std::sort(names.begin(), names.end());
  std::string s;
  const size_t shown = std::min<size_t>(names.size(), 4);
  for (size_t i = 0; i < shown; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > shown) s += " and " + std::to_string(names.size() - shown) + " more";
  return s;
}

}  // namespace

std::string outputMarkerText(const std::string& kind) {
  nlohmann::json j{
      {"format", "matbricks-output"}, {"version", 1}, {"kind", kind}, {"generator", "matbricks " MB_VERSION}};
  return j.dump(2) + "\n";
}

bool carriesOutputMarker(const fs::path& dir) {
  std::ifstream in(dir / kOutputMarkerName, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  auto j = nlohmann::json::parse(s.str(), nullptr, false);
  return j.is_object() && j.value("format", "") == "matbricks-output";
}

void refuseOverlap(const fs::path& output, const std::string& outputWhat, const std::vector<ProtectedPath>& inputs) {
  bool outputExists = false;
  const std::vector<FileId> outChain = ancestry(output, outputExists);
  for (const auto& in : inputs) {
    if (in.path.empty()) continue;
    bool inputExists = false;
    const std::vector<FileId> inChain = ancestry(in.path, inputExists);
    std::string relation;
    if (inputExists) {
      const FileId inId = inChain.front();
      if (outputExists && outChain.front() == inId)
        relation = "is";
      else if (outputExists && contains(inChain, outChain.front()))
        relation = "contains";
      else if (contains(outChain, inId))
        relation = "lies inside";
    } else {
      relation = lexicalRelation(output, in.path);  // e.g. another output not written yet
    }
    if (relation.empty()) continue;
    fail("E-OUTPUT-OVERLAPS-INPUT", output,
         "the " + outputWhat + " '" + output.string() + "' " + relation + " the " + in.what + " '" + in.path.string() +
             "': an output may not be, contain or lie inside what the command reads; nothing was written",
         "choose an output outside the inputs");
  }
}

void checkOutputDirectory(const fs::path& dir) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir, ec);
  if (!fs::exists(st)) return;
  if (!fs::is_directory(st))
    fail("E-OUTPUT-NOT-PACKAGE", dir,
         "output directory '" + dir.string() + "' exists and is not a directory; nothing was changed",
         "give a new or empty directory, or one matbricks wrote");
  if (fs::is_empty(dir, ec) && !ec) return;
  if (carriesOutputMarker(dir)) return;
  fail("E-OUTPUT-NOT-PACKAGE", dir,
       "output directory '" + dir.string() + "' holds files matbricks did not write (" + someEntries(dir) + "; no " +
           kOutputMarkerName +
           " marker): it is replaced only when new, empty or a matbricks output; nothing was changed",
       "give a new or empty directory, or remove this one yourself");
}

void checkOutputFile(const fs::path& file) {
  std::error_code ec;
  const fs::path target = resolvedOutputFile(file);
  const fs::file_status st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    fail("E-OUTPUT-NOT-FILE", file,
         "output '" + file.string() + "' exists and is not a regular file (" +
             (fs::is_directory(st) ? std::string("a directory") : std::string("a device, socket or pipe")) +
             "): a file output never replaces it; nothing was changed");
  const fs::path parent = fs::absolute(target).parent_path();
  if (!fs::is_directory(parent, ec))
    fail("E-IO", file, "cannot write file: directory '" + parent.string() + "' does not exist");
}

fs::path resolvedOutputFile(const fs::path& file) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(file, ec))) {
    fs::path resolved = fs::weakly_canonical(fs::absolute(file), ec);
    if (!ec) return resolved;
  }
  return file;
}

}  // namespace mb
