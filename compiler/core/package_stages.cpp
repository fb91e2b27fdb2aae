#include "core/package_stages.hpp"

#include <sstream>

namespace mb {

std::vector<std::string> packageStageNames(const PackageStages& stages) {
  std::vector<std::string> names;
  if (stages.kernel) names.push_back("kernel");
  if (stages.fragment) names.push_back("fragment");
  return names;
}

bool parsePackageStages(const std::string& text, PackageStages& stages, std::string& why) {
  PackageStages parsed{false, false};
  // getline drops a trailing empty field: a trailing comma is an empty name.
  std::istringstream in(text.empty() || text.back() == ',' ? text + "," : text);
  for (std::string name; std::getline(in, name, ',');) {
    bool* stage = name == "kernel" ? &parsed.kernel : name == "fragment" ? &parsed.fragment : nullptr;
    if (!stage) {
      why = "unknown stage '" + name + "' (the stages are kernel and fragment)";
      return false;
    }
    if (*stage) {
      why = "stage '" + name + "' is named twice";
      return false;
    }
    *stage = true;
  }
  if (!parsed.kernel && !parsed.fragment) {
    why = "no stage selected (give kernel, fragment or kernel,fragment)";
    return false;
  }
  stages = parsed;
  return true;
}

}  // namespace mb
