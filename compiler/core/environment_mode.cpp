#include "core/environment_mode.hpp"

#include "core/axis_names.hpp"

namespace mb {
namespace {

const AxisNames<EnvironmentMode>& environmentModeAxis() {
  static const AxisNames<EnvironmentMode> a{
      {EnvironmentMode::None, EnvironmentMode::Sh, EnvironmentMode::IblLut, EnvironmentMode::IblAnalytic},
      {"none", "sh", "ibl_lut", "ibl_analytic"}};
  return a;
}

}  // namespace

const std::string& environmentModeName(EnvironmentMode e) { return environmentModeAxis().name(e); }
const std::vector<EnvironmentMode>& allEnvironmentModes() { return environmentModeAxis().values; }
const std::vector<std::string>& allEnvironmentModeNames() { return environmentModeAxis().names; }
std::optional<EnvironmentMode> parseEnvironmentMode(std::string_view name) { return environmentModeAxis().parse(name); }
std::vector<EnvironmentMode> parseEnvironmentModes(const std::vector<std::string>& names) {
  return environmentModeAxis().parseAll(names, "environment mode");
}
std::vector<std::string> environmentModeNames(const std::vector<EnvironmentMode>& modes) {
  return environmentModeAxis().namesOf(modes);
}

bool isIbl(EnvironmentMode e) { return e == EnvironmentMode::IblLut || e == EnvironmentMode::IblAnalytic; }
bool usesDfgLut(EnvironmentMode e) { return e == EnvironmentMode::IblLut; }

}  // namespace mb
