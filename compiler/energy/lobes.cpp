#include "energy/lobes.hpp"

#include <map>
#include <set>

namespace mb::energy {
namespace {

struct Theory {
  Expectation expectation;
  const char* note;
};

// Smith's bound: Int G1(v) (v.h)+ D(h) d(omega_h) = n.v (Heitz 2014, "Understanding the
// Masking-Shadowing Function", eq. 2), so any G <= G1(v) gives an albedo <= 1. Forms without
// that bound may exceed 1; the measurement decides.
const std::map<std::string, Theory>& theories() {
  static const std::map<std::string, Theory> t{
      {"v_smith_ggx_correlated",
       {Expectation::Conserving,
        "exact single-scattering Smith: G2 <= G1(v), albedo <= 1 (Heitz 2014 eq. 2); the deficit is the "
        "multiple scattering it leaves out (Kulla & Conty 2017)"}},
      {"v_smith_ggx_separable",
       {Expectation::Conserving,
        "G1(v) G1(l) <= G1(v): bounded like the correlated form, and darker (Heitz 2014 sec. 6)"}},
      {"v_smith_ggx_correlated_aniso",
       {Expectation::Conserving, "exact anisotropic Smith (Heitz 2014 eqs. 86, 99): G2 <= G1(v), albedo <= 1"}},
      {"v_smith_ggx_separable_aniso",
       {Expectation::Conserving, "anisotropic G1(v) G1(l) <= G1(v) (Heitz 2014 eqs. 86, 98): albedo <= 1"}},
      {"v_smith_ggx_correlated_fast",
       {Expectation::Unbounded, "Hammon 2017's linearized correlated denominator: a fit, not bounded by G1(v)"}},
      {"v_schlick_ggx_ue4",
       {Expectation::Unbounded, "Schlick's rational G1 with k = (r+1)^2/8 (Karis 2013): a fit, not bounded by G1(v)"}},
      {"v_schlick_ggx_ibl",
       {Expectation::Unbounded, "Schlick's rational G1 with k = alpha/2 (Karis 2013): a fit, not bounded by G1(v)"}},
      {"v_kelemen",
       {Expectation::Unbounded,
        "G = (n.l)(n.v)/(l.h)^2 (Kelemen & Szirmay-Kalos 2001): roughness-free, not bounded by G1(v)"}},
      {"v_neumann",
       {Expectation::Unbounded, "G = min(n.l, n.v) (Neumann et al. 1999): roughness-free, not bounded by G1(v)"}},
      {"v_implicit", {Expectation::Unbounded, "G = (n.l)(n.v) (Hoffman 2013): roughness-free, not bounded by G1(v)"}},
      {"v_cook_torrance",
       {Expectation::Unbounded,
        "V-cavity G (Cook & Torrance 1982 after Blinn 1977): masking of v-grooves, not of the microsurface "
        "whose D it multiplies"}},
      {"v_charlie",
       {Expectation::Unbounded,
        "sheen by design: Charlie's Lambda is a fit and the terminator softening changes it (Estevez & Kulla "
        "2017 sec. 3-4); engines scale sheen by its own albedo (DFG channel 2)"}},
      {"v_charlie_no_softening",
       {Expectation::Unbounded, "sheen by design: Charlie's Lambda is a fit (Estevez & Kulla 2017 sec. 3)"}},
      {"v_ashikhmin",
       {Expectation::Unbounded,
        "sheen by design: Ashikhmin's smooth denominator 1/(4(n.l + n.v - n.l n.v)) has no masking "
        "(Neubelt & Pettineo 2013)"}},
      {"diffuse_lambert", {Expectation::Conserving, "Int (n.l)/pi d(omega) = 1 exactly"}},
      {"diffuse_fabric_lambert", {Expectation::Conserving, "lerp(1, 0.5, alpha)/pi: albedo lerp(1, 0.5, alpha) <= 1"}},
      {"diffuse_disney_burley",
       {Expectation::NotConserving,
        "the retro-reflection factor F_D90 = 0.5 + 2 r (l.h)^2 is not normalized (Burley 2012 sec. 5.3); the "
        "reason for Frostbite's renormalized form (Lagarde & de Rousiers 2014)"}},
      {"diffuse_disney_renormalized",
       {Expectation::Unbounded,
        "Burley's diffuse with energyBias/energyFactor (Lagarde & de Rousiers 2014 listing 1): a "
        "renormalization, not a bound"}},
      {"diffuse_activision_multiscatter",
       {Expectation::Unbounded, "a fit to simulated multiple scattering of Lambertian microfacets (Chan 2018 sec. 5)"}},
  };
  return t;
}

Theory theoryOf(const std::string& id) {
  auto it = theories().find(id);
  if (it != theories().end()) return it->second;
  return {Expectation::Unbounded, "no energy statement recorded for this brick"};
}

// Which D each quadrature map follows, and which V bricks pair with it.
const std::map<std::string, HalfVectorMapKind>& distributionMaps() {
  static const std::map<std::string, HalfVectorMapKind> m{
      {"d_ggx", HalfVectorMapKind::Ggx},         {"d_beckmann", HalfVectorMapKind::Beckmann},
      {"d_charlie", HalfVectorMapKind::Charlie}, {"d_ashikhmin", HalfVectorMapKind::Ashikhmin},
      {"d_ggx_aniso", HalfVectorMapKind::Ggx},
  };
  return m;
}

const std::set<std::string>& sheenVisibilities() {
  static const std::set<std::string> s{"v_charlie", "v_charlie_no_softening", "v_ashikhmin"};
  return s;
}

void addPair(std::vector<Lobe>& out, const ShaderLibrary& lib, const std::string& d, const std::string& v,
             LobeKind kind) {
  const Brick* db = lib.findBrick(d);
  const Brick* vb = lib.findBrick(v);
  if (!db || !vb) return;
  Theory t = theoryOf(v);
  out.push_back({d + " * " + v, kind, {db, vb}, distributionMaps().at(d), t.expectation, t.note});
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

std::vector<Lobe> energyLobes(const ShaderLibrary& lib) {
  std::vector<Lobe> out;
  // GGX D with every non-sheen V; Beckmann D with the V-cavity (the original Cook-Torrance).
  for (const auto& v : lib.bricksOfSlot("specular_v"))
    if (!sheenVisibilities().count(v)) addPair(out, lib, "d_ggx", v, LobeKind::Specular);
  addPair(out, lib, "d_beckmann", "v_cook_torrance", LobeKind::Specular);
  // Sheen: Charlie D with the Charlie and Ashikhmin V; Ashikhmin D with Ashikhmin V (seed 004).
  for (const auto& v : sheenVisibilities()) addPair(out, lib, "d_charlie", v, LobeKind::Sheen);
  addPair(out, lib, "d_ashikhmin", "v_ashikhmin", LobeKind::Sheen);
  // Anisotropic GGX with every anisotropic V.
  for (const auto& v : lib.bricksOfSlot("specular_v_aniso")) addPair(out, lib, "d_ggx_aniso", v, LobeKind::Anisotropic);
  for (const auto& id : lib.bricksOfSlot("diffuse")) {
    Theory t = theoryOf(id);
    out.push_back({id, LobeKind::Diffuse, {lib.findBrick(id)}, HalfVectorMapKind::Cosine, t.expectation, t.note});
  }
  return out;
}

}  // namespace mb::energy
