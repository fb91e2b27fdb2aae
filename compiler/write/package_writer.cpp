#include "write/package_writer.hpp"

#include <xxhash.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

#include "core/diagnostics.hpp"
#include "write/output_paths.hpp"
#include "write/owned_tree.hpp"
#include "write/spill_file.hpp"

namespace mb {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void ioError(const fs::path& p, const std::string& what) {
  throw DiagnosticError({{Severity::Error, "E-IO", {p.string(), 0, 0}, what, ""}});
}

// Fault injection for the crash-safety test (tests/test_output_safety.cpp): with
// MATBRICKS_FAULT_KILL_AT=<point> the process SIGKILLs itself there, as a user's kill -9 or an
// OOM kill would at that moment. Unset in normal use; documented in docs/cli.md.
void faultPoint(const char* point) {
  static const char* at = std::getenv("MATBRICKS_FAULT_KILL_AT");
  if (at && std::strcmp(at, point) == 0) ::kill(::getpid(), SIGKILL);
}

// Temporaries live next to the target as ".<name>.matbricks-<new|old|tmp>.<pid>.<n>", each a
// directory holding our marker from its first write on, so a later run can tell ours (the
// exact pattern, a process that is gone, and the marker inside) from anything else.
std::string temporaryPrefix(const fs::path& target, const char* kind) {
  return "." + target.filename().string() + ".matbricks-" + kind + ".";
}

bool everything(const std::string&) { return true; }

// A file inside a temporary directory, its bytes hashed as they go to disk (for the marker).
class HashingFileBuf : public std::streambuf {
 public:
  explicit HashingFileBuf(const fs::path& p)
      : fd_(::open(p.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666)),
        state_(XXH64_createState()) {
    XXH64_reset(state_, 0);
    setp(buffer_, buffer_ + sizeof buffer_);
  }
  ~HashingFileBuf() override {
    if (fd_ >= 0) ::close(fd_);
    XXH64_freeState(state_);
  }
  // Flushes and closes; false if anything failed.
  bool finish(MarkedFile& file) {
    bool ok = fd_ >= 0 && flush();
    if (fd_ >= 0 && ::close(fd_) != 0) ok = false;
    fd_ = -1;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(XXH64_digest(state_)));
    file = {size_, hex};
    return ok && !failed_;
  }

 protected:
  int_type overflow(int_type ch) override {
    if (!flush()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return flush() ? 0 : -1; }

 private:
  bool flush() {
    const char* p = pbase();
    size_t left = static_cast<size_t>(pptr() - pbase());
    XXH64_update(state_, p, left);
    size_ += left;
    while (left > 0 && fd_ >= 0) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        failed_ = true;
        break;
      }
      p += n;
      left -= static_cast<size_t>(n);
    }
    setp(buffer_, buffer_ + sizeof buffer_);
    return !failed_ && fd_ >= 0;
  }
  int fd_;
  XXH64_state_t* state_;
  std::uint64_t size_ = 0;
  bool failed_ = false;
  char buffer_[1 << 16];
};

MarkedFile writeMarked(const fs::path& p, const std::function<void(std::ostream&)>& write) {
  HashingFileBuf buf(p);
  std::ostream out(&buf);
  write(out);
  MarkedFile file;
  if (!buf.finish(file) || !out) ioError(p, std::string("cannot write file: ") + std::strerror(errno));
  return file;
}

fs::path temporaryName(const fs::path& target, const char* which) {
  static std::atomic<uint64_t> counter{0};
  return target.parent_path() /
         (temporaryPrefix(target, which) + std::to_string(::getpid()) + "." + std::to_string(counter++));
}

// Creates a new temporary directory beside `target` holding only a marker of `kind`.
fs::path createTemporary(const fs::path& target, const char* which, const std::string& kind) {
  for (int attempt = 0;; ++attempt) {
    const fs::path dir = temporaryName(target, which);
    if (::mkdir(dir.c_str(), 0777) != 0) {
      if (errno == EEXIST && attempt < 100) continue;  // a killed run of a reused pid left it
      ioError(target, std::string(which == std::string("tmp") ? "cannot write file" : "cannot write the output") +
                          ": cannot create a temporary directory beside it: " + std::strerror(errno));
    }
    try {
      writeMarked(dir / kOutputMarkerName, [&](std::ostream& out) { out << outputMarkerHeader(kind); });
    } catch (...) {
      removeOwnedTree(dir, everything);
      throw;
    }
    return dir;
  }
}

bool processAlive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// The pid of a temporary's name "<prefix><pid>.<n>", or 0 when the name is not exactly that.
long temporaryPid(const std::string& name, const std::string& prefix) {
  if (name.rfind(prefix, 0) != 0) return 0;
  const std::string rest = name.substr(prefix.size());
  const size_t dot = rest.find('.');
  auto digits = [](const std::string& s) {
    return !s.empty() && s.size() < 19 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (dot == std::string::npos || !digits(rest.substr(0, dot)) || !digits(rest.substr(dot + 1))) return 0;
  return std::stol(rest.substr(0, dot));
}

// Removes a temporary this or a killed run made: a finished output's files by its marker's
// list (an old package swapped out), a staging directory's (marker without its end line, or
// no readable marker yet) whole. Never crosses a mount point; the marker goes last.
bool removeTemporary(const fs::path& dir, const std::function<void()>& afterEach = {}) {
  std::string why;
  const std::optional<OutputMarker> marker = readOutputMarker(dir, why);
  if (marker && marker->version >= 2 && marker->complete)
    return removeOwnedTree(
        dir, [&](const std::string& rel) { return marker->files.count(rel) > 0; }, afterEach);
  return removeOwnedTree(dir, everything, afterEach);
}

// Removes what an earlier, killed run left beside `target`: only directories named by our
// pattern whose process is gone and that hold our marker, or nothing but an unfinished one
// (killed while writing it), or nothing at all (killed between mkdir and the marker). If the
// target itself is missing and a killed run had moved the old package aside (the rename
// fallback's window), the old package is put back first.
void cleanLeftovers(const fs::path& target) {
  std::error_code ec;
  const std::string oldPrefix = temporaryPrefix(target, "old");
  std::vector<fs::path> ours;  // collected first: the directory is changed below
  for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    long pid = 0;
    for (const char* which : {"new", "old", "tmp"})
      if (!pid) pid = temporaryPid(name, temporaryPrefix(target, which));
    std::error_code e2;
    if (!pid || processAlive(pid) || !fs::is_directory(it->symlink_status(e2))) continue;  // a concurrent run's stays
    bool marked = carriesOutputMarker(it->path()) || fs::is_empty(it->path(), e2);
    if (!marked) {  // only a marker cut short by the kill
      const fs::directory_iterator first(it->path(), e2);
      marked = !e2 && first != fs::directory_iterator() && first->path().filename() == kOutputMarkerName &&
               std::next(fs::directory_iterator(it->path(), e2)) == fs::directory_iterator();
    }
    if (marked) ours.push_back(it->path());
  }
  for (const auto& dir : ours) {
    std::string why;
    const auto marker = readOutputMarker(dir, why);
    if (dir.filename().string().rfind(oldPrefix, 0) == 0 && marker && marker->complete &&
        !fs::exists(fs::symlink_status(target, ec)) && ::rename(dir.c_str(), target.c_str()) == 0)
      continue;
    removeTemporary(dir);
  }
}

// Runs `write`; if it fails, the temporary directory goes and the failure is reported as E-IO.
void writeIntoStaging(const fs::path& staging, const std::function<void()>& write) {
  try {
    write();
  } catch (const fs::filesystem_error& e) {
    removeTemporary(staging);
    ioError(e.path1(), std::string("cannot write package: ") + e.code().message());
  } catch (...) {
    removeTemporary(staging);
    throw;
  }
}

// A staging directory beside `target` holding only the marker's header, written first: from
// then on a leftover staging directory is recognisably ours.
fs::path createStaging(const fs::path& target, const std::string& kind) {
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  cleanLeftovers(target);
  return createTemporary(target, "new", kind);
}

// A relative path inside the output: plain components only, and not the marker.
void checkRelativePath(const std::string& rel) {
  const fs::path p(rel);
  bool ok = !rel.empty() && p.is_relative() && rel.back() != '/';
  for (const auto& part : p) ok = ok && !part.empty() && part != "." && part != "..";
  ok = ok && p.begin()->string() != kOutputMarkerName;
  if (!ok)
    throw DiagnosticError({{Severity::Error,
                            "E-OUTPUT-NAME",
                            {rel, 0, 0},
                            "'" + rel + "' is not a file name inside the output directory; nothing was written",
                            ""}});
}

}  // namespace

PackageWriter::PackageWriter(std::string kind) : kind_(std::move(kind)) {}

PackageWriter::~PackageWriter() {
  if (!staging_.empty()) removeTemporary(staging_);
}

void PackageWriter::stage(const fs::path& dir) {
  stagedFor_ = resolvedOutputDirectory(dir);
  checkOutputDirectory(stagedFor_);
  staging_ = createStaging(stagedFor_, kind_);
}

void PackageWriter::record(const std::string& relativePath, const MarkedFile& file) {
  if (!records_) records_ = std::make_unique<SpillFile>();
  records_->append(outputMarkerLine(relativePath, file));
  ++recordCount_;
}

void PackageWriter::writeInto(const fs::path& staging, const std::string& relativePath,
                              const std::function<void(std::ostream&)>& write) {
  const fs::path p = staging / relativePath;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);
  if (ec) ioError(p.parent_path(), "cannot write package: " + ec.message());
  record(relativePath, writeMarked(p, write));
}

void PackageWriter::addFileStreamed(const std::string& relativePath, const std::function<void(std::ostream&)>& write) {
  checkRelativePath(relativePath);
  if (staging_.empty()) {
    std::ostringstream text;
    write(text);
    files_[relativePath] = text.str();
    return;
  }
  // As the buffered writer's "staging-half": some files written, not all.
  if (++streamed_ == 2) faultPoint("staging-half");
  writeInto(staging_, relativePath, write);
}

void PackageWriter::addFile(const std::string& relativePath, std::string bytes) {
  checkRelativePath(relativePath);
  if (staging_.empty()) {
    files_[relativePath] = std::move(bytes);
    return;
  }
  addFileStreamed(relativePath,
                  [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

void PackageWriter::addFile(const std::string& relativePath, const std::vector<uint32_t>& words) {
  addFile(relativePath, std::string(reinterpret_cast<const char*>(words.data()), words.size() * 4));
}

void PackageWriter::finishMarker(const fs::path& staging) {
  // Sorted, so the marker is the same bytes whatever order the files were written in (a
  // streamed build's windows, -j): the package stays byte-identical across runs. Held only
  // here, at the end: some 100 bytes per file.
  std::vector<std::string> lines;
  if (records_) {
    std::ostringstream text;
    records_->copyTo(text);
    std::istringstream in(text.str());
    for (std::string line; std::getline(in, line);) lines.push_back(line + "\n");
  }
  std::sort(lines.begin(), lines.end());
  std::ofstream marker(staging / kOutputMarkerName, std::ios::binary | std::ios::app);
  for (const auto& line : lines) marker << line;
  marker << outputMarkerEnd(recordCount_);
  marker.close();
  if (!marker) ioError(staging / kOutputMarkerName, "cannot write the output marker");
}

void PackageWriter::commit(const fs::path& dir) {
  const fs::path target = resolvedOutputDirectory(dir);
  std::error_code ec;
  fs::path staging;
  if (!staging_.empty()) {
    if (target != stagedFor_) ioError(target, "internal: committed to another directory than staged");
    staging = staging_;
    staging_.clear();  // from here on, this function owns it
  } else {
    staging = createStaging(target, kind_);
  }
  writeIntoStaging(staging, [&] {
    size_t written = 0;
    for (const auto& file : files_) {
      // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
      const std::string& bytes = file.second;
      if (written++ == files_.size() / 2) faultPoint("staging-half");
      writeInto(staging, file.first,
                [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
    }
    finishMarker(staging);
  });
  faultPoint("before-swap");
  // The CLI checked before any work, and stage() when it began; checked again right before
  // anything is replaced.
  try {
    checkOutputDirectory(target);
  } catch (...) {
    removeTemporary(staging);
    throw;
  }
  const bool replacing = fs::exists(target) && !fs::is_empty(target, ec);
  if (!replacing) {
    // A missing target, or an empty directory: rename(2) replaces an empty directory in one step.
    if (::rename(staging.c_str(), target.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      removeTemporary(staging);
      ioError(target, "cannot move the output into place: " + why);
    }
    return;
  }
  // The old output goes by its own marker's list, marker last, so a kill part way leaves a
  // directory the next run recognises (cleanLeftovers) and finishes removing.
  auto removeOld = [](const fs::path& old) {
    removeTemporary(old, [n = 0]() mutable {
      if (++n == 2) faultPoint("removing-old");
    });
  };
  // One atomic step: the old output and the new one trade names (Linux renameat2
  // RENAME_EXCHANGE), so a reader or a kill at any moment sees one complete output.
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    faultPoint("after-swap");
    removeOld(staging);  // now the old output
    return;
  }
  if (errno != EINVAL && errno != ENOSYS) {
    const std::string why = std::strerror(errno);
    removeTemporary(staging);
    ioError(target, "cannot replace the output directory: " + why);
  }
  // A file system without RENAME_EXCHANGE: move the old one aside, the new one in. A kill in
  // between leaves the old one under an "old" name, which the next run puts back.
  const fs::path previous = temporaryName(target, "old");
  fs::rename(target, previous, ec);
  if (ec) {
    removeTemporary(staging);
    ioError(target, "cannot replace the output directory: " + ec.message());
  }
  faultPoint("after-aside");
  fs::rename(staging, target, ec);
  if (ec) {
    std::error_code restore;
    fs::rename(previous, target, restore);
    removeTemporary(staging);
    ioError(target, "cannot move the output into place: " + ec.message());
  }
  removeOld(previous);
}

void PackageWriter::writeFileAtomically(const fs::path& file, const std::string& bytes) {
  // Never replaces a directory or a device (checkOutputFile); a symlink's target is replaced,
  // not the link.
  checkOutputFile(file);
  const fs::path target = fs::absolute(resolvedOutputFile(file));  // its directory is scanned for leftovers
  // The bytes go into a marked temporary directory beside the target and are renamed out of
  // it: a run killed before the rename leaves that directory, which the next write of this
  // file recognises and removes (cleanLeftovers); never a bare temporary file.
  cleanLeftovers(target);
  const fs::path temporary = createTemporary(target, "tmp", "temporary");
  const fs::path inside = temporary / "content";  // never the marker's name, whatever the target's
  try {
    writeMarked(inside,
                [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
    faultPoint("file-written");
    if (::rename(inside.c_str(), target.c_str()) != 0)
      ioError(file, std::string("cannot write file: ") + std::strerror(errno));
  } catch (...) {
    removeTemporary(temporary);
    throw;
  }
  removeTemporary(temporary);
}

}  // namespace mb
