#include "write/package_writer.hpp"

#include <xxhash.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>
#include <unistd.h>

#include "core/diagnostics.hpp"

namespace mb {
namespace fs = std::filesystem;

void PackageWriter::addFile(const std::string& relativePath, std::string bytes) {
  files_[relativePath] = std::move(bytes);
}

void PackageWriter::addFile(const std::string& relativePath, const std::vector<uint32_t>& words) {
  files_[relativePath] = std::string(reinterpret_cast<const char*>(words.data()), words.size() * 4);
}

[[noreturn]] static void ioError(const fs::path& p, const std::string& what) {
  throw DiagnosticError({{Severity::Error, "E-IO", {p.string(), 0, 0}, what, ""}});
}

void PackageWriter::commit(const fs::path& dir) const {
  fs::path target = fs::absolute(dir).lexically_normal();
  if (target.filename().empty()) target = target.parent_path();
  std::string suffix = "." + std::to_string(::getpid());
  fs::path staging = target.string() + ".staging" + suffix;
  fs::path previous = target.string() + ".previous" + suffix;
  std::error_code ec;
  fs::create_directories(target.parent_path(), ec);
  fs::remove_all(staging, ec);
  try {
    fs::create_directories(staging);
    for (const auto& [rel, bytes] : files_) {
      fs::path p = staging / rel;
      fs::create_directories(p.parent_path());
      std::ofstream out(p, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      out.close();
      if (!out) ioError(p, "cannot write file");
    }
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(staging, ec);
    ioError(e.path1(), std::string("cannot write package: ") + e.code().message());
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  bool hadPrevious = fs::exists(target);
  if (hadPrevious) {
    fs::rename(target, previous, ec);
    if (ec) {
      fs::remove_all(staging, ec);
      ioError(target, "cannot replace existing output directory");
    }
  }
  fs::rename(staging, target, ec);
  if (ec) {
    if (hadPrevious) fs::rename(previous, target, ec);
    fs::remove_all(staging, ec);
    ioError(target, "cannot move package into place");
  }
  if (hadPrevious) fs::remove_all(previous, ec);
}

bool replaceFileAtomically(const fs::path& file, const std::string& bytes) {
  static std::atomic<uint64_t> counter{0};
  std::ostringstream name;
  name << file.filename().string() << ".tmp." << ::getpid() << "." << std::hash<std::thread::id>{}(std::this_thread::get_id())
       << "." << counter++;
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
  if (!replaceFileAtomically(file, bytes)) ioError(file, "cannot write file");
}

std::string contentHash(const void* data, size_t size) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(XXH64(data, size, 0)));
  return buf;
}

}  // namespace mb
