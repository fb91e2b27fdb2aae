#include "energy/lobes.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace mb::energy {
namespace {

// The library's words for a brick's energy facts (library/shader_library.hpp BrickEnergy).
LobeKind lobeKindOf(const std::string& lobe) {
  static const std::map<std::string, LobeKind> m{{"specular", LobeKind::Specular},
                                                 {"sheen", LobeKind::Sheen},
                                                 {"anisotropic", LobeKind::Anisotropic},
                                                 {"diffuse", LobeKind::Diffuse}};
  return m.at(lobe);
}

HalfVectorMapKind mapKindOf(const std::string& map) {
  static const std::map<std::string, HalfVectorMapKind> m{{"ggx", HalfVectorMapKind::Ggx},
                                                          {"beckmann", HalfVectorMapKind::Beckmann},
                                                          {"charlie", HalfVectorMapKind::Charlie},
                                                          {"ashikhmin", HalfVectorMapKind::Ashikhmin}};
  return m.at(map);
}

Expectation expectationOf(const std::string& e) {
  static const std::map<std::string, Expectation> m{{"conserving", Expectation::Conserving},
                                                    {"not_conserving", Expectation::NotConserving},
                                                    {"unbounded", Expectation::Unbounded}};
  return m.at(e);
}

// The bricks of the library's slots whose energy role is `role`, in library order, less the
// ones their entry excludes.
std::vector<const Brick*> bricksWithRole(const ShaderLibrary& lib, const std::string& role) {
  std::vector<const Brick*> out;
  for (const auto& b : lib.bricks()) {
    const Slot* slot = lib.findSlot(b.slot);
    if (slot && slot->energyRole == role && b.energy.excluded.empty()) out.push_back(&b);
  }
  return out;
}

bool pairs(const Brick& d, const Brick& v) {
  if (v.energy.lobe != d.energy.lobe) return false;
  const auto& listed = d.energy.visibilities;
  return d.energy.allVisibilities || std::find(listed.begin(), listed.end(), v.id) != listed.end();
}

}  // namespace

const char* lobeKindName(LobeKind kind) {
  switch (kind) {
    case LobeKind::Specular:
      return "specular";
    case LobeKind::Sheen:
      return "sheen";
    case LobeKind::Anisotropic:
      return "anisotropic";
    case LobeKind::Diffuse:
      return "diffuse";
  }
  return "?";
}

const char* expectationName(Expectation e) {
  switch (e) {
    case Expectation::Conserving:
      return "conserving";
    case Expectation::NotConserving:
      return "not conserving";
    case Expectation::Unbounded:
      return "no bound";
  }
  return "?";
}

// Smith's bound: Int G1(v) (v.h)+ D(h) d(omega_h) = n.v (Heitz 2014, "Understanding the
// Masking-Shadowing Function", eq. 2), so any G <= G1(v) gives an albedo <= 1; forms without
// that bound may exceed 1 and the measurement decides. Each V and diffuse brick's manifest
// "energy" entry records which case it is, with the source. Lobes are listed by kind, then
// by the D's quadrature map (lobes sharing nodes stay together), then in library order.
std::vector<Lobe> energyLobes(const ShaderLibrary& lib) {
  std::vector<Lobe> out;
  auto distributions = bricksWithRole(lib, "distribution");
  std::stable_sort(distributions.begin(), distributions.end(), [](const Brick* a, const Brick* b) {
    return std::pair(lobeKindOf(a->energy.lobe), mapKindOf(a->energy.halfVectorMap)) <
           std::pair(lobeKindOf(b->energy.lobe), mapKindOf(b->energy.halfVectorMap));
  });
  auto visibilities = bricksWithRole(lib, "visibility");
  for (const Brick* d : distributions)
    for (const Brick* v : visibilities)
      if (pairs(*d, *v))
        out.push_back({d->id + " * " + v->id,
                       lobeKindOf(d->energy.lobe),
                       {d, v},
                       mapKindOf(d->energy.halfVectorMap),
                       expectationOf(v->energy.expectation),
                       v->energy.note});
  for (const Brick* b : bricksWithRole(lib, "diffuse"))
    out.push_back({b->id,
                   LobeKind::Diffuse,
                   {b},
                   HalfVectorMapKind::Cosine,
                   expectationOf(b->energy.expectation),
                   b->energy.note});
  return out;
}

const Lobe* dfgLobe(const std::vector<Lobe>& lobes, const ShaderLibrary& lib) {
  const Brick* visibility = lib.brickForKernelRole("dfg_visibility");
  for (const Lobe& lobe : lobes)
    if (lobe.kind == LobeKind::Specular && lobe.map == HalfVectorMapKind::Ggx && lobe.factors.size() == 2 &&
        lobe.factors[1] == visibility)
      return &lobe;
  return nullptr;
}

}  // namespace mb::energy
