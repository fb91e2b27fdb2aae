// Which inputs are roughnesses, as data (docs/formats.md, slot.json "params" and model
// "inputs"): at fp16 a roughness input starts at Filament's floor (precision.hpp:
// MIN_PERCEPTUAL_ROUGHNESS on mobile, and its square for alpha), so a new slot or model input
// that is a roughness says so in its own declaration instead of in a C++ list of names.
#include <algorithm>

#include "library/library_loader.hpp"

namespace mb {

const std::vector<std::string>& roughnessKindNames() {
  static const std::vector<std::string> v{"perceptual", "alpha"};
  return v;
}

RoughnessKind LibraryLoader::readRoughnessKind(JsonFields& f, const std::string& inputPtr, const std::string& name,
                                               std::optional<ValueType> type) {
  std::string ptr = inputPtr + "/roughness";
  RoughnessKind kind = RoughnessKind::None;
  SourceLocation at = f.valueAt(inputPtr);
  if (f.find(ptr)) {
    at = f.valueAt(ptr);
    auto word = oneOf(f, ptr, roughnessKindNames());
    if (!word) return kind;
    if (type && *type != ValueType::Float) {
      f.error("E-INVALID-VALUE", at,
              "'" + JsonFields::describe(ptr) + "' is given for '" + name + "', which is a " +
                  std::string(toString(*type)) + ": only a float input is a roughness");
      return kind;
    }
    kind = *word == "alpha" ? RoughnessKind::Alpha : RoughnessKind::Perceptual;
  }
  if (type == ValueType::Float) roughnessDeclarations_.push_back({name, kind, at});
  return kind;
}

// A probe's domain is keyed by input name (validate/precision_domain.hpp), so every float
// input of one name must be the same kind; the first one that says a kind sets it.
void LibraryLoader::checkRoughnessKinds() {
  auto word = [](RoughnessKind k) {
    return k == RoughnessKind::None
               ? std::string("no \"roughness\"")
               : "\"roughness\": \"" + std::string(k == RoughnessKind::Alpha ? "alpha" : "perceptual") + "\"";
  };
  std::map<std::string, const RoughnessDeclaration*> first;
  for (const auto& d : roughnessDeclarations_)
    if (d.kind != RoughnessKind::None) first.emplace(d.name, &d);
  for (const auto& d : roughnessDeclarations_) {
    auto it = first.find(d.name);
    if (it == first.end()) continue;
    const RoughnessDeclaration& set = *it->second;
    if (d.kind == set.kind) continue;
    sink_.error("E-INVALID-VALUE", d.at,
                "input '" + d.name + "' has " + word(d.kind) + ", but the input of that name at " +
                    formatLocation(set.at) + " has " + word(set.kind) +
                    ": probes look inputs up by name, so all inputs named '" + d.name + "' must say the same");
  }
  for (const auto& [name, d] : first) data_.roughnessKinds[name] = d->kind;
}

}  // namespace mb
