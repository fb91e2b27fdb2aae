#include "write/owned_tree.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <xxhash.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <memory>
#include <set>

namespace mb {
namespace fs = std::filesystem;

namespace {

// A descriptor closed when it goes out of scope.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
};

std::vector<std::string> entryNames(int dirFd) {
  std::vector<std::string> names;
  const int own = ::dup(dirFd);  // closedir closes it; dirFd stays open
  if (own < 0) return names;
  std::unique_ptr<DIR, int (*)(DIR*)> d(::fdopendir(own), ::closedir);
  if (!d) {
    ::close(own);
    return names;
  }
  ::rewinddir(d.get());
  while (const dirent* e = ::readdir(d.get())) {
    const std::string name = e->d_name;
    if (name != "." && name != "..") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A directory on another file system, or a bind mount of the same one (statx's
// STATX_ATTR_MOUNT_ROOT, Linux 5.8; st_dev alone does not see a bind mount from one device).
bool isMountPoint(int dirFd, const std::string& name, dev_t parentDev, const struct stat& st) {
  if (st.st_dev != parentDev) return true;
  struct statx sx {};
  if (::statx(dirFd, name.c_str(), AT_SYMLINK_NOFOLLOW | AT_NO_AUTOMOUNT, STATX_BASIC_STATS, &sx) != 0) return false;
  return (sx.stx_attributes_mask & STATX_ATTR_MOUNT_ROOT) && (sx.stx_attributes & STATX_ATTR_MOUNT_ROOT);
}

// contentHash (core/content_hash.hpp) of a file, read through `dirFd` without following links.
std::string hashFileAt(int dirFd, const std::string& name) {
  Fd fd(::openat(dirFd, name.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC));
  if (fd.fd < 0) return "";
  std::unique_ptr<XXH64_state_t, XXH_errorcode (*)(XXH64_state_t*)> state(XXH64_createState(), XXH64_freeState);
  XXH64_reset(state.get(), 0);
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(fd.fd, buffer.data(), buffer.size());
    if (n < 0) return "";
    if (n == 0) break;
    XXH64_update(state.get(), buffer.data(), static_cast<size_t>(n));
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(XXH64_digest(state.get())));
  return hex;
}

struct Scan {
  const OutputMarker& marker;
  std::set<std::string> listedDirs;  // "spirv", "fragment/hlsl": directories leading to listed files
  std::vector<ForeignEntry> found;

  void directory(int dirFd, dev_t dev, const std::string& prefix) {
    for (const std::string& name : entryNames(dirFd)) {
      if (prefix.empty() && name == kOutputMarkerName) continue;
      const std::string rel = prefix + name;
      struct stat st {};
      if (::fstatat(dirFd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) continue;  // gone meanwhile
      if (S_ISDIR(st.st_mode)) {
        if (isMountPoint(dirFd, name, dev, st)) {
          found.push_back({rel + "/", "is a mount point", true});
        } else if (!listedDirs.count(rel)) {
          found.push_back({rel + "/", "not listed"});
        } else {
          Fd sub(::openat(dirFd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
          if (sub.fd < 0)
            found.push_back({rel + "/", "is not readable"});
          else
            directory(sub.fd, dev, rel + "/");
        }
        continue;
      }
      const auto listed = marker.files.find(rel);
      if (S_ISLNK(st.st_mode))
        found.push_back({rel, "is a symlink"});
      else if (!S_ISREG(st.st_mode))
        found.push_back({rel, "is not a regular file"});
      else if (listed == marker.files.end())
        found.push_back({rel, "not listed"});
      else if (static_cast<std::uint64_t>(st.st_size) != listed->second.size ||
               hashFileAt(dirFd, name) != listed->second.xxh64)
        found.push_back({rel, "changed since matbricks wrote it"});
    }
  }
};

// Removes what is owned under the open directory; true when nothing but (at the top) the
// marker is left in it.
bool removeIn(int dirFd, dev_t dev, const std::string& prefix, const std::function<bool(const std::string&)>& owned,
              const std::function<void()>& afterEach) {
  bool empty = true;
  for (const std::string& name : entryNames(dirFd)) {
    if (prefix.empty() && name == kOutputMarkerName) continue;
    const std::string rel = prefix + name;
    struct stat st {};
    if (::fstatat(dirFd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    bool removed = false;
    if (S_ISDIR(st.st_mode)) {
      if (!isMountPoint(dirFd, name, dev, st)) {
        Fd sub(::openat(dirFd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        removed = sub.fd >= 0 && removeIn(sub.fd, dev, rel + "/", owned, afterEach) &&
                  ::unlinkat(dirFd, name.c_str(), AT_REMOVEDIR) == 0;
      }
    } else {
      removed = owned(rel) && ::unlinkat(dirFd, name.c_str(), 0) == 0;
    }
    if (removed && afterEach) afterEach();
    empty = empty && removed;
  }
  return empty;
}

}  // namespace

std::vector<ForeignEntry> foreignEntries(const fs::path& dir, const OutputMarker& marker) {
  Scan scan{marker, {}, {}};
  for (const auto& [path, file] : marker.files)
    for (fs::path p = fs::path(path).parent_path(); !p.empty(); p = p.parent_path()) scan.listedDirs.insert(p.string());
  Fd root(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  struct stat st {};
  if (root.fd < 0 || ::fstat(root.fd, &st) != 0) return {{".", "is not readable"}};
  scan.directory(root.fd, st.st_dev, "");
  std::stable_partition(scan.found.begin(), scan.found.end(), [](const ForeignEntry& e) { return e.mountPoint; });
  return scan.found;
}

bool removeOwnedTree(const fs::path& dir, const std::function<bool(const std::string&)>& owned,
                     const std::function<void()>& afterEach) {
  struct stat st {};
  {
    Fd root(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (root.fd < 0 || ::fstat(root.fd, &st) != 0) return false;
    if (!removeIn(root.fd, st.st_dev, "", owned, afterEach)) return false;
    if (::unlinkat(root.fd, kOutputMarkerName, 0) != 0 && errno != ENOENT) return false;
  }
  return ::rmdir(dir.c_str()) == 0;
}

}  // namespace mb
