#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace mb {
namespace fs = std::filesystem;

namespace {

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string fileTypeName(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string tooLarge(const fs::path& path, const InputKind& kind, const std::string& size) {
  return quoted(path) + " has " + size + " bytes: a " + kind.what + " is at most " + std::to_string(kind.maxBytes) +
         " bytes";
}

}  // namespace

InputFile::InputFile(int fd, fs::path path, InputKind kind, std::uintmax_t size)
    : fd_(fd), path_(std::move(path)), kind_(kind), size_(size) {}

InputFile::InputFile(InputFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      path_(std::move(other.path_)),
      kind_(other.kind_),
      size_(other.size_),
      consumed_(other.consumed_) {}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
    kind_ = other.kind_;
    size_ = other.size_;
    consumed_ = other.consumed_;
  }
  return *this;
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<InputFile> InputFile::open(const fs::path& path, const InputKind& kind, InputFileError& error) {
  // O_NONBLOCK: opening a FIFO for reading blocks until a writer appears; non-blocking, the
  // open returns at once and fstat below refuses it. O_NOCTTY: a terminal never becomes ours.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    error = {"E-FILE-NOT-FOUND",
             "cannot open file " + quoted(path) + " (" + std::strerror(err) + "): expected a readable " + kind.what};
    return std::nullopt;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const mode_t mode = st.st_mode;
    ::close(fd);
    error = {"E-FILE-NOT-REGULAR",
             quoted(path) + " is " + fileTypeName(mode) + ": expected a " + kind.what + " (a regular file)"};
    return std::nullopt;
  }
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > kind.maxBytes) {
    ::close(fd);
    error = {"E-FILE-TOO-LARGE", tooLarge(path, kind, std::to_string(size))};
    return std::nullopt;
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return InputFile(fd, path, kind, size);
}

long InputFile::read(char* buffer, std::size_t n, InputFileError& error) {
  // One byte beyond the limit may be read, to tell "exactly at the limit" from "grew past it".
  const std::uintmax_t allowed = kind_.maxBytes + 1 - consumed_;
  if (n > allowed) n = static_cast<std::size_t>(allowed);
  ssize_t got;
  do {
    got = ::read(fd_, buffer, n);
  } while (got < 0 && errno == EINTR);
  if (got < 0) {
    const int err = errno;
    error = {"E-IO", "cannot read " + quoted(path_) + ": " + std::strerror(err)};
    return -1;
  }
  consumed_ += static_cast<std::uintmax_t>(got);
  if (consumed_ > kind_.maxBytes) {
    error = {"E-FILE-TOO-LARGE", tooLarge(path_, kind_, "more than " + std::to_string(kind_.maxBytes))};
    return -1;
  }
  return static_cast<long>(got);
}

long InputFile::readAt(std::uintmax_t offset, char* buffer, std::size_t n, InputFileError& error) {
  if (offset > kind_.maxBytes) n = 0;
  n = static_cast<std::size_t>(std::min<std::uintmax_t>(n, kind_.maxBytes - std::min(offset, kind_.maxBytes)));
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd_, buffer + done, n - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      const int err = errno;
      error = {"E-IO", "cannot read " + quoted(path_) + ": " + std::strerror(err)};
      return -1;
    }
    if (got == 0) break;
    done += static_cast<std::size_t>(got);
  }
  return static_cast<long>(done);
}

std::optional<std::string> InputFile::readAll(InputFileError& error) {
  std::string out;
  out.reserve(static_cast<std::size_t>(size_));
  char buffer[1 << 16];
  for (;;) {
    const long got = read(buffer, sizeof buffer, error);
    if (got < 0) return std::nullopt;
    if (got == 0) return out;
    out.append(buffer, static_cast<std::size_t>(got));
  }
}

std::optional<std::string> readInputFile(const fs::path& path, const InputKind& kind, InputFileError& error) {
  auto file = InputFile::open(path, kind, error);
  if (!file) return std::nullopt;
  return file->readAll(error);
}

std::string readInputFileOrThrow(const fs::path& path, const InputKind& kind, const SourceLocation& at) {
  InputFileError error;
  if (auto text = readInputFile(path, kind, error)) return std::move(*text);
  const SourceLocation where = at.file.empty() ? SourceLocation(path.string(), 0, 0) : at;
  throw DiagnosticError({{Severity::Error, error.code, where, error.message}});
}

}  // namespace mb
