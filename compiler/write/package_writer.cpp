#include "write/package_writer.hpp"

#include <xxhash.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "core/diagnostics.hpp"
#include "write/output_paths.hpp"

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

// Temporaries live next to the target as ".<name>.matbricks-<new|old>.<pid>.<n>", so a later
// run can tell ours (the pattern, and the marker inside) from anything else.
std::string temporaryPrefix(const fs::path& target, const char* kind) {
  return "." + target.filename().string() + ".matbricks-" + kind + ".";
}

fs::path temporaryPath(const fs::path& target, const char* kind) {
  static std::atomic<uint64_t> counter{0};
  return target.parent_path() /
         (temporaryPrefix(target, kind) + std::to_string(::getpid()) + "." + std::to_string(counter++));
}

bool processAlive(long pid) { return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM); }

// Removes what an earlier, killed run left beside `target`: only directories named by our
// pattern whose process is gone and that hold our marker (or nothing at all: killed between
// mkdir and the marker). If the target itself is missing and a killed run had moved the old
// package aside (the rename fallback's window), the old package is put back first.
void cleanLeftovers(const fs::path& target) {
  std::error_code ec;
  const std::string oldPrefix = temporaryPrefix(target, "old"), newPrefix = temporaryPrefix(target, "new");
  std::vector<fs::path> olds, news;  // collected first: the directory is changed below
  for (fs::directory_iterator it(target.parent_path(), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    for (auto [prefix, list] : {std::pair{&oldPrefix, &olds}, std::pair{&newPrefix, &news}}) {
      if (name.rfind(*prefix, 0) != 0) continue;
      std::error_code e2;
      const long pid = std::strtol(name.c_str() + prefix->size(), nullptr, 10);
      if (it->is_directory(e2) && !processAlive(pid) &&  // a concurrent run's stays
          (carriesOutputMarker(it->path()) || fs::is_empty(it->path(), e2)))
        list->push_back(it->path());
    }
  }
  for (const auto& old : olds)
    if (!fs::exists(fs::symlink_status(target, ec))) fs::rename(old, target, ec);
  for (const auto& list : {olds, news})
    for (const auto& p : list) fs::remove_all(p, ec);
}

void writeOne(const fs::path& p, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(p, std::ios::binary);
  write(out);
  out.close();
  if (!out) ioError(p, "cannot write file");
}

void writeOne(const fs::path& p, const std::string& bytes) {
  writeOne(p, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

void writeStaged(const fs::path& staging, const std::map<std::string, std::string>& files) {
  size_t written = 0;
  for (const auto& [rel, bytes] : files) {
    if (written++ == files.size() / 2) faultPoint("staging-half");
    fs::path p = staging / rel;
    fs::create_directories(p.parent_path());
    writeOne(p, bytes);
  }
}

// Runs `write`; if it fails, the staging directory goes and the failure is reported as E-IO.
void writeIntoStaging(const fs::path& staging, const std::function<void()>& write) {
  std::error_code ec;
  try {
    write();
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    ioError(e.path1(), std::string("cannot write package: ") + e.code().message());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
}

// A staging directory beside `target` holding only the marker, written first: from then on a
// leftover staging directory is recognisably ours.
fs::path createStaging(const fs::path& target, const std::string& marker) {
  checkOutputDirectory(target);
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  cleanLeftovers(target);
  const fs::path staging = temporaryPath(target, "new");
  writeIntoStaging(staging, [&] {
    fs::create_directory(staging);
    writeOne(staging / kOutputMarkerName, marker);
  });
  return staging;
}

fs::path normalTarget(const fs::path& dir) {
  fs::path target = fs::absolute(dir).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();
  return target;
}

}  // namespace

PackageWriter::~PackageWriter() {
  std::error_code ec;
  if (!staging_.empty()) fs::remove_all(staging_, ec);
}

void PackageWriter::stage(const fs::path& dir) {
  stagedFor_ = normalTarget(dir);
  staging_ = createStaging(stagedFor_, outputMarkerText(kind_));
}

void PackageWriter::addFileStreamed(const std::string& relativePath, const std::function<void(std::ostream&)>& write) {
  if (staging_.empty()) {
    std::ostringstream text;
    write(text);
    files_[relativePath] = text.str();
    return;
  }
  // As the buffered writer's "staging-half": some files written, not all.
  if (++streamed_ == 2) faultPoint("staging-half");
  const fs::path p = staging_ / relativePath;
  std::error_code ec;
  fs::create_directories(p.parent_path(), ec);
  try {
    writeOne(p, write);
  } catch (const fs::filesystem_error& e) {
    ioError(e.path1(), std::string("cannot write package: ") + e.code().message());
  }
}

void PackageWriter::addFile(const std::string& relativePath, std::string bytes) {
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

void PackageWriter::commit(const fs::path& dir) {
  const fs::path target = normalTarget(dir);
  std::error_code ec;
  fs::path staging;
  if (!staging_.empty()) {
    if (target != stagedFor_) ioError(target, "internal: committed to another directory than staged");
    // The CLI checked before any work, stage() when it began; checked again right before
    // replacing anything.
    checkOutputDirectory(target);
    staging = staging_;
    staging_.clear();  // from here on, this function owns it
  } else {
    staging = createStaging(target, outputMarkerText(kind_));
    writeIntoStaging(staging, [&] { writeStaged(staging, files_); });
  }
  faultPoint("before-swap");
  const bool replacing = fs::exists(target) && !fs::is_empty(target, ec);
  if (!replacing) {
    // A missing target, or an empty directory: rename(2) replaces an empty directory in one step.
    if (::rename(staging.c_str(), target.c_str()) != 0) {
      const std::string why = std::strerror(errno);
      fs::remove_all(staging, ec);
      ioError(target, "cannot move the output into place: " + why);
    }
    return;
  }
  // One atomic step: the old package and the new one trade names (Linux renameat2
  // RENAME_EXCHANGE), so a reader or a kill at any moment sees one complete package.
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    faultPoint("after-swap");
    fs::remove_all(staging, ec);  // now the old package; a kill here leaves it for cleanLeftovers
    return;
  }
  if (errno != EINVAL && errno != ENOSYS) {
    const std::string why = std::strerror(errno);
    fs::remove_all(staging, ec);
    ioError(target, "cannot replace the output directory: " + why);
  }
  // A file system without RENAME_EXCHANGE: move the old one aside, the new one in. A kill in
  // between leaves the old one under an "old" name, which the next run puts back.
  const fs::path previous = temporaryPath(target, "old");
  fs::rename(target, previous, ec);
  if (ec) {
    fs::remove_all(staging, ec);
    ioError(target, "cannot replace the output directory: " + ec.message());
  }
  faultPoint("after-aside");
  fs::rename(staging, target, ec);
  if (ec) {
    std::error_code restore;
    fs::rename(previous, target, restore);
    fs::remove_all(staging, restore);
    ioError(target, "cannot move the output into place: " + ec.message());
  }
  fs::remove_all(previous, ec);
}

bool replaceFileAtomically(const fs::path& file, const std::string& bytes) {
  static std::atomic<uint64_t> counter{0};
  std::ostringstream name;
  name << file.filename().string() << ".tmp." << ::getpid() << "."
       << std::hash<std::thread::id>{}(std::this_thread::get_id()) << "." << counter++;
  const fs::path tmp = file.parent_path() / name.str();
  std::error_code ec;
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      return false;
    }
  }
  fs::rename(tmp, file, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

void PackageWriter::writeFileAtomically(const fs::path& file, const std::string& bytes) {
  // Never replaces a directory or a device (checkOutputFile); a symlink's target is replaced,
  // not the link.
  checkOutputFile(file);
  const fs::path target = resolvedOutputFile(file);
  if (!replaceFileAtomically(target, bytes)) ioError(file, "cannot write file");
}

std::string contentHash(const void* data, size_t size) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(data, size, 0)));
  return buf;
}

}  // namespace mb
