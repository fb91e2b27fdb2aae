#include "load/gltf_external_files.hpp"

#include <cctype>
#include <filesystem>

#include "load/gltf_container.hpp"

namespace mb {
namespace {

// RFC 3986 percent-decoding; a malformed escape is kept as written.
std::string percentDecoded(const std::string& uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

// "scheme:" before any '/' marks an absolute URI (data:, http:, file:), not a relative path.
bool hasScheme(const std::string& uri) {
  const size_t colon = uri.find(':'), slash = uri.find('/');
  return colon != std::string::npos && (slash == std::string::npos || colon < slash);
}

}  // namespace

std::vector<std::string> gltfExternalFiles(const std::string& gltfPath) {
  std::vector<std::string> files;
  try {
    GltfContainerInfo info;
    const JsonDocument doc = loadGltfMaterialJson(gltfPath, info);
    const std::filesystem::path dir = std::filesystem::path(gltfPath).parent_path();
    for (const char* array : {"buffers", "images"}) {
      const auto it = doc.root().find(array);
      if (it == doc.root().end() || !it->is_array()) continue;
      for (const auto& entry : *it) {
        if (!entry.is_object() || !entry.contains("uri") || !entry["uri"].is_string()) continue;
        const std::string uri = entry["uri"].get<std::string>();
        if (uri.empty() || hasScheme(uri)) continue;
        files.push_back((dir / percentDecoded(uri)).lexically_normal().string());
      }
    }
  } catch (const DiagnosticError&) {
    // The loader reports what is wrong with the file itself.
  }
  return files;
}

}  // namespace mb
