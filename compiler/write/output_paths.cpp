#include "write/output_paths.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <optional>

#include "core/diagnostics.hpp"
#include "write/owned_tree.hpp"

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

// "notes.txt not listed, spirv/ab.spv changed since matbricks wrote it and 3 more"
std::string listed(const std::vector<ForeignEntry>& entries) {
  std::string s;
  const size_t shown = std::min<size_t>(entries.size(), 4);
  for (size_t i = 0; i < shown; ++i) s += (i ? ", " : "") + entries[i].path + " " + entries[i].why;
  if (entries.size() > shown) s += " and " + std::to_string(entries.size() - shown) + " more";
  return s;
}

}  // namespace

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
  std::string why;
  const std::optional<OutputMarker> marker = readOutputMarker(dir, why);
  if (!marker) {
    const bool present = fs::exists(fs::symlink_status(dir / kOutputMarkerName, ec));
    fail("E-OUTPUT-NOT-PACKAGE", dir,
         "output directory '" + dir.string() + "' holds files matbricks did not write (" + someEntries(dir) + "; " +
             (present ? "its " + std::string(kOutputMarkerName) + " is not ours: " + why
                      : "no " + std::string(kOutputMarkerName) + " marker") +
             "): it is replaced only when new, empty or a matbricks output; nothing was changed",
         "give a new or empty directory, or remove this one yourself");
  }
  const std::vector<ForeignEntry> foreign = foreignEntries(dir, *marker);
  if (!foreign.empty() && foreign.front().mountPoint)
    fail("E-OUTPUT-MOUNT", dir,
         "output directory '" + dir.string() + "' has a mount point inside (" + foreign.front().path +
             "): matbricks never removes anything across file systems; nothing was changed",
         "unmount it, or give another directory");
  if (marker->version < 2 && !foreign.empty())
    fail("E-OUTPUT-UNLISTED", dir,
         "output directory '" + dir.string() +
             "' carries a marker of an older matbricks, which lists no files, and holds " + listed(foreign) +
             ": only what a marker lists is ever removed; nothing was changed",
         "remove the directory yourself once; directories written from now on list their files");
  if (!marker->complete)
    fail("E-OUTPUT-UNLISTED", dir,
         "output directory '" + dir.string() +
             "' carries an unfinished marker (of a staging directory, not a finished " +
             "output): its files are not known to be matbricks'; nothing was changed",
         "remove the directory yourself");
  if (!foreign.empty())
    fail("E-OUTPUT-UNLISTED", dir,
         "output directory '" + dir.string() + "' holds what its " + kOutputMarkerName + " does not list (" +
             listed(foreign) + "): matbricks replaces only the files it wrote; nothing was changed",
         "move those out, or remove the directory yourself");
}

fs::path resolvedOutputDirectory(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(dir), ec);
  if (ec) p = fs::absolute(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  // weakly_canonical stops at a dangling symlink; follow it by hand (as the kernel would, at
  // most 40 links: ELOOP).
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hops) {
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) break;
    p = (to.is_absolute() ? to : p.parent_path() / to).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
  }
  return p;
}

void checkOutputName(const std::string& name, const std::string& option, const SourceLocation& at) {
  std::string why;
  if (name.empty())
    why = "is empty";
  else if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos)
    why = "holds a path separator";
  else if (name == "." || name == "..")
    why = "is '" + name + "'";
  else if (name.front() == '.')
    why = "starts with a dot (a hidden file, or the package's own marker)";
  else if (std::any_of(name.begin(), name.end(),
                       [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }))
    why = "holds a control character";
  if (why.empty()) return;
  throw DiagnosticError({{Severity::Error, "E-OUTPUT-NAME", at,
                          option + " '" + name + "' " + why +
                              ": it names one file inside the output directory, not a path; nothing was written",
                          "give a plain file name such as materials.hpp"}});
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
