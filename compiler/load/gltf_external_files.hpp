// The files a glTF document names besides itself: buffers[].uri and images[].uri that are
// not data: URIs (glTF 2.0 spec, "URIs"). Material import reads neither, but they are the
// user's files all the same: no command's output may overwrite them (write/output_paths.hpp).
#pragma once
#include <string>
#include <vector>

namespace mb {

// Resolved against the glTF file's directory, percent-decoded; URIs with a scheme other than
// a plain relative path (data:, http:, ...) are skipped. An unreadable or malformed file
// yields nothing: loading it reports that.
std::vector<std::string> gltfExternalFiles(const std::string& gltfPath);

}  // namespace mb
