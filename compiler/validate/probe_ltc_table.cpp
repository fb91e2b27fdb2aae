#include "validate/probe_ltc_table.hpp"

#include <map>
#include <mutex>

namespace mb {

std::shared_ptr<const ProbeLtcTable> probeLtcTable(const ShaderLibrary& lib) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const ProbeLtcTable>> loaded;
  const std::string path = (lib.root() / ltc::kLibraryTableFile).string();
  std::lock_guard lock(mutex);
  auto& slot = loaded[path];
  if (!slot) {
    auto t = std::make_shared<ProbeLtcTable>();
    t->table = ltc::loadTable(path);
    t->sheen = ltc::loadTable((lib.root() / ltc::kLibrarySheenTableFile).string());
    t->texels = ltc::tableTexels(t->table, t->sheen);
    slot = std::move(t);
  }
  return slot;
}

ref::LtcTexel ProbeLtcTable::texel(ref::LtcLobe lobe, double NoV, double perceptualRoughness) const {
  return ltcTableTexel(lobe == ref::LtcLobe::Sheen ? sheen : table, NoV, perceptualRoughness);
}

ref::LtcTexel ltcTableTexel(const ltc::Table& table, double NoV, double perceptualRoughness) {
  const ltc::TableSample s = ltc::sampleBilinear(table, perceptualRoughness, NoV);
  return ref::LtcTexel{s.minv[0][0], s.minv[0][2], s.minv[2][0], s.minv[2][2], s.norm, s.fresnel};
}

}  // namespace mb
