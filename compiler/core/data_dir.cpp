#include "core/data_dir.hpp"

namespace mb {
namespace fs = std::filesystem;

fs::path dataRoot() {
  static const fs::path root = [] {
    std::error_code ec;
    // Linux: the running executable, whatever the current directory or argv[0].
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
      const fs::path installed = (exe.parent_path() / ".." / "share" / "matbricks").lexically_normal();
      if (fs::exists(installed / "shaderlib" / "manifest.json", ec)) return installed;
    }
    return compiledSourceDir();
  }();
  return root;
}

fs::path compiledSourceDir() { return fs::path(MB_SOURCE_DIR); }

}  // namespace mb
