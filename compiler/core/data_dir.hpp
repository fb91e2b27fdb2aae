// Where matbricks finds its data (the shader library, the example materials): installed
// beside the program as <prefix>/share/matbricks (cmake --install, the .deb), else the source
// tree it was built from. An installed tool thus keeps working with the source tree gone
// (docs/install.md).
#pragma once
#include <filesystem>

namespace mb {

// <directory of the running program>/../share/matbricks when that holds a shader library,
// else the source tree compiled in (MB_SOURCE_DIR).
std::filesystem::path dataRoot();

// The source tree this program was built from (for tests and benchmarks, which run in it).
std::filesystem::path compiledSourceDir();

}  // namespace mb
