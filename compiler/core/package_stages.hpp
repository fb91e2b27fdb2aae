// Which shader stages a package holds (`compile --stages`, docs/package.md "Stages"), shared by
// the command line, the CMake function's STAGES, the compiler (what a unit builds) and the
// package writer (what the manifest and header list).
#pragma once
#include <string>
#include <vector>

namespace mb {

// The compute kernel (docs/package.md "Kernel ABI") and the fragment shader
// (docs/fragment-stage.md). An engine that draws with fragment shaders only does not pay for
// kernels, and the other way round; the include files (include/<key>.*) come with either.
struct PackageStages {
  bool kernel = true;
  bool fragment = true;
  bool operator==(const PackageStages&) const = default;
};

// "kernel", "fragment", in that order, the selected ones.
std::vector<std::string> packageStageNames(const PackageStages& stages);
// Parses a comma-separated list of "kernel" and "fragment" (each at most once, at least one).
// False with `why` for anything else.
bool parsePackageStages(const std::string& text, PackageStages& stages, std::string& why);

}  // namespace mb
