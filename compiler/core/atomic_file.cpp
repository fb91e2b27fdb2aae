#include "core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

namespace mb {
namespace fs = std::filesystem;

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

}  // namespace mb
