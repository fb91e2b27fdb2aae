#include "core/environment_mode.hpp"

#include "core/axis_names.hpp"

namespace mb {
namespace {

const AxisNames<EnvironmentMode>& axis() {
  static const AxisNames<EnvironmentMode> a{
      {EnvironmentMode::None, EnvironmentMode::Sh, EnvironmentMode::IblLut, EnvironmentMode::IblAnalytic},
      {"none", "sh", "ibl_lut", "ibl_analytic"}};
  return a;
}

}  // namespace

const std::string& environmentModeName(EnvironmentMode e) { return axis().name(e); }
const std::vector<EnvironmentMode>& allEnvironmentModes() { return axis().values; }
const std::vector<std::string>& allEnvironmentModeNames() { return axis().names; }
std::optional<EnvironmentMode> parseEnvironmentMode(std::string_view name) { return axis().parse(name); }
std::vector<EnvironmentMode> parseEnvironmentModes(const std::vector<std::string>& names) {
  return axis().parseAll(names, "environment mode");
}
std::vector<std::string> environmentModeNames(const std::vector<EnvironmentMode>& modes) {
  return axis().namesOf(modes);
}

bool isIbl(EnvironmentMode e) { return e == EnvironmentMode::IblLut || e == EnvironmentMode::IblAnalytic; }
bool usesDfgLut(EnvironmentMode e) { return e == EnvironmentMode::IblLut; }

}  // namespace mb
