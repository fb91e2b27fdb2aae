// INTERIM (replaced by quality selection and folding).
#include "permute/specialize.hpp"

namespace mb {

MaterialDesc applyQuality(const MaterialDesc& material, const std::string&, const ShaderLibrary&) { return material; }
std::optional<std::string> foldBlocker(const MaterialDesc&, const std::string&, const std::vector<MaterialUse>&,
                                       const ShaderLibrary&) {
  return std::string("not implemented");
}
MaterialDesc foldFeatures(const MaterialDesc& material, const std::vector<std::string>&, const ShaderLibrary&) {
  return material;
}
MaterialDesc featureComplete(const MaterialDesc& material, const MaterialUse&, const ShaderLibrary&) { return material; }

}  // namespace mb
