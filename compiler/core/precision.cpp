#include "core/precision.hpp"

#include "core/axis_names.hpp"

namespace mb {
namespace {

const AxisNames<Precision>& precisionAxis() {
  static const AxisNames<Precision> a{{Precision::Fp32, Precision::Fp16}, {"fp32", "fp16"}};
  return a;
}

}  // namespace

const std::string& precisionName(Precision p) { return precisionAxis().name(p); }
const std::vector<Precision>& allPrecisions() { return precisionAxis().values; }
const std::vector<std::string>& allPrecisionNames() { return precisionAxis().names; }
std::optional<Precision> parsePrecision(std::string_view name) { return precisionAxis().parse(name); }
std::vector<Precision> parsePrecisions(const std::vector<std::string>& names) {
  return precisionAxis().parseAll(names, "precision");
}

}  // namespace mb
