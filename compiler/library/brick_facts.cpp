// Facts about single bricks that the compiler acts on (docs/architecture.md "Adding a
// brick"): kept in the brick's own manifest entry so that a new brick brings them along
// instead of needing a C++ table beside it. Read here, checked once every slot is loaded.
#include <algorithm>

#include "library/library_loader.hpp"

namespace mb {

// "fp16_twin": the brick an fp16 permutation binds instead of this one. Only a brick of the
// same slot can stand in (same signature, same role).
void LibraryLoader::readFp16Twin(JsonFields& f, const std::string& ptr, Brick& b) {
  if (!f.find(ptr)) return;
  auto twin = identifier(f, ptr, "fp16_twin");
  if (!twin) return;
  if (*twin == b.id) {
    f.error("E-INVALID-VALUE", f.valueAt(ptr), "brick '" + b.id + "' cannot be its own fp16_twin");
    return;
  }
  b.fp16Twin = *twin;
  brickReferences_.push_back({*twin, b.slot, "fp16_twin of '" + b.id + "'", f.valueAt(ptr)});
}

const std::vector<std::string>& brickEnergyRoles() {
  static const std::vector<std::string> v{"distribution", "visibility", "diffuse"};
  return v;
}
const std::vector<std::string>& brickEnergyLobes() {
  static const std::vector<std::string> v{"specular", "sheen", "anisotropic"};
  return v;
}
const std::vector<std::string>& brickEnergyMaps() {
  static const std::vector<std::string> v{"ggx", "beckmann", "charlie", "ashikhmin"};
  return v;
}
const std::vector<std::string>& brickEnergyExpectations() {
  static const std::vector<std::string> v{"conserving", "not_conserving", "unbounded"};
  return v;
}

// A string that must be one of `allowed`.
std::optional<std::string> LibraryLoader::oneOf(JsonFields& f, const std::string& ptr,
                                                const std::vector<std::string>& allowed) {
  auto s = f.string(ptr);
  if (!s || std::find(allowed.begin(), allowed.end(), *s) != allowed.end()) return s;
  f.error("E-INVALID-VALUE", f.valueAt(ptr),
          "'" + JsonFields::describe(ptr) + "' is '" + *s + "': expected one of " + quotedList(allowed),
          didYouMean(*s, allowed));
  return std::nullopt;
}

// "energy": every brick of a slot with an energy role says how the energy checks treat it
// (or why they leave it out), so that a new D, V or diffuse brick cannot be silently
// skipped; a brick of any other slot has none.
void LibraryLoader::readBrickEnergy(JsonFields& f, const std::string& brickPtr, const Slot& slot, Brick& b) {
  std::string ptr = brickPtr + "/energy";
  if (slot.energyRole.empty()) {
    if (f.find(ptr))
      f.error("E-UNKNOWN-FIELD", f.keyAt(ptr),
              "'energy' given, but slot '" + slot.name + "' has no energy role (its slot.json has no \"energy\")");
    return;
  }
  if (!f.find(ptr)) {
    f.error("E-MISSING-FIELD", f.valueAt(brickPtr),
            "brick '" + b.id + "' needs an 'energy' entry: the bricks of slot '" + slot.name + "' are " +
                slot.energyRole + " bricks of the energy checks (or say {\"excluded\": why})");
    return;
  }
  if (!f.isObject(ptr)) return;
  if (f.find(ptr)->contains("excluded")) {
    if (f.object(ptr, {"excluded"}, {}, "energy")) b.energy.excluded = nonEmpty(f, ptr + "/excluded").value_or("");
    return;
  }
  if (slot.energyRole == "distribution") return readDistributionEnergy(f, ptr, b);
  bool visibility = slot.energyRole == "visibility";
  std::vector<std::string> required{"expectation", "note"};
  if (visibility) required.push_back("lobe");
  if (!f.object(ptr, required, {}, "energy")) return;
  b.energy.lobe = visibility ? oneOf(f, ptr + "/lobe", brickEnergyLobes()).value_or("") : "diffuse";
  b.energy.expectation = oneOf(f, ptr + "/expectation", brickEnergyExpectations()).value_or("");
  b.energy.note = nonEmpty(f, ptr + "/note").value_or("");
}

// A D brick: {"lobe", "half_vector_map", "visibility": "all" or [V brick ids]}.
void LibraryLoader::readDistributionEnergy(JsonFields& f, const std::string& ptr, Brick& b) {
  if (!f.object(ptr, {"lobe", "half_vector_map", "visibility"}, {}, "energy")) return;
  b.energy.lobe = oneOf(f, ptr + "/lobe", brickEnergyLobes()).value_or("");
  b.energy.halfVectorMap = oneOf(f, ptr + "/half_vector_map", brickEnergyMaps()).value_or("");
  std::string vptr = ptr + "/visibility";
  const nlohmann::json* v = f.find(vptr);
  if (v->is_string()) {
    if (oneOf(f, vptr, {"all"})) b.energy.allVisibilities = true;
    return;
  }
  auto ids = f.strings(vptr);
  if (!ids) return;
  if (ids->empty())
    f.error("E-EMPTY-FIELD", f.valueAt(vptr), "'" + JsonFields::describe(vptr) + "' must name at least one V brick");
  b.energy.visibilities = *ids;
  for (size_t i = 0; i < ids->size(); ++i)
    energyPairs_.push_back(
        {(*ids)[i], b.energy.lobe, "energy.visibility of '" + b.id + "'", f.valueAt(JsonFields::element(vptr, i))});
}

// The kernels' roles, each with the slot whose signature the kernel calls it with.
const std::vector<KernelRole>& brickKernelRoles() {
  static const std::vector<KernelRole> v{
      {"hammersley", "hammersley", "the DFG LUT's Hammersley estimators and the environment prefilter"},
      {"sample_ggx", "importance_sample", "the DFG LUT's Hammersley estimators and the environment prefilter"},
      {"dfg_visibility", "specular_v", "the DFG LUT's GGX channels"},
      {"cloth_dfg_d", "specular_d", "the DFG LUT's cloth channel"},
      {"cloth_dfg_v", "specular_v", "the DFG LUT's cloth channel"},
      {"prefilter_d", "specular_d", "the environment prefilter"},
      {"multiscatter", "energy_compensation", "the energy checks' multiscatter compensation"},
      {"preview_tonemap", "tonemap", "the preview's default tonemap"}};
  return v;
}

// "kernel_roles": the library's own kernels (lut/, preview/, energy/) find their bricks by these, so a
// role names a slot (the signature the kernel calls) and is taken by one brick only.
void LibraryLoader::readKernelRoles(JsonFields& f, const std::string& ptr, const Slot& slot, Brick& b) {
  if (!f.find(ptr)) return;
  auto roles = f.strings(ptr);
  if (!roles) return;
  std::vector<std::string> names;
  for (const auto& r : brickKernelRoles()) names.push_back(r.role);
  for (size_t i = 0; i < roles->size(); ++i) {
    std::string eptr = JsonFields::element(ptr, i);
    auto role = oneOf(f, eptr, names);
    if (!role) continue;
    const KernelRole& kr = brickKernelRoles()[std::find(names.begin(), names.end(), *role) - names.begin()];
    SourceLocation at = f.valueAt(eptr);
    if (kr.slot != slot.name) {
      f.error("E-INVALID-VALUE", at,
              "kernel role '" + *role + "' is for a brick of slot '" + kr.slot + "' (" + kr.kernel +
                  " calls it with that slot's signature), but '" + b.id + "' is of slot '" + slot.name + "'");
      continue;
    }
    auto [it, fresh] = kernelRoleHolders_.emplace(*role, std::make_pair(b.id, at));
    if (!fresh) {
      f.error("E-DUPLICATE-NAME", at,
              "kernel role '" + *role + "' is already taken by brick '" + it->second.first + "' at " +
                  formatLocation(it->second.second) + ": " + kr.kernel + " calls one brick per role");
      continue;
    }
    b.kernelRoles.push_back(*role);
  }
}

void LibraryLoader::checkBrickReferences() {
  for (const auto& r : brickReferences_) {
    const Brick* b = findLoadedBrick(r.id);
    if (b && b->slot == r.slot) continue;
    sink_.error("E-UNKNOWN-BRICK", r.at,
                r.what + " names '" + r.id + "', which is not a brick of slot '" + r.slot + "'",
                didYouMean(r.id, loadedBricksOf(r.slot)));
  }
  // A V brick is a brick of a slot whose energy role is "visibility".
  auto isVisibility = [&](const Brick& b) {
    return std::any_of(data_.slots.begin(), data_.slots.end(),
                       [&](const Slot& s) { return s.name == b.slot && s.energyRole == "visibility"; });
  };
  for (const auto& p : energyPairs_) {
    const Brick* b = findLoadedBrick(p.visibility);
    if (b && isVisibility(*b) && b->energy.lobe == p.lobe) continue;
    std::vector<std::string> candidates;
    for (const auto& v : data_.bricks)
      if (isVisibility(v) && v.energy.lobe == p.lobe) candidates.push_back(v.id);
    sink_.error("E-UNKNOWN-BRICK", p.at,
                p.what + " names '" + p.visibility + "', which is not a V brick of the '" + p.lobe +
                    "' lobe (those are " + quotedList(candidates) + ")",
                didYouMean(p.visibility, candidates));
  }
}

}  // namespace mb
