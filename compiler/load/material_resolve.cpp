// MaterialSource -> MaterialDesc: the checks every description form shares (JSON, the macro
// form, glTF import), so a material means the same whatever it was written in. Rules:
// docs/formats.md "Material JSON" and docs/models.md (roles, features, inputs).
#include "load/material_resolve.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cfloat>
#include <map>
#include <optional>
#include <set>
#include <tuple>

#include "core/json_fields.hpp"
#include "library/value_json.hpp"
#include "load/generated_names_source.hpp"
#include "load/glsl_names.hpp"

namespace mb {

std::string clipped(const std::string& text) {
  constexpr size_t kMax = 60;
  return text.size() <= kMax ? text : text.substr(0, kMax) + "...";
}

std::string suggest(const std::string& word, const std::vector<std::string>& candidates) {
  // didYouMean is an edit distance against every candidate: skip it for absurdly long words.
  return word.size() > 64 ? std::string() : didYouMean(word, candidates);
}

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// A user parameter without a range gets [0, 1]: the domain of colours, factors and texture
// values, which is what user parameters of a surface function almost always are.
const Range kUserDefaultRange{0.0, 1.0};

// The user's `surface` function must exist: without it the emitted call fails in glslang at
// a line of the generated file instead of at the user's. A token scan (no std::regex: its
// recursion overflows the stack on megabyte inputs) for `void surface (`.
bool definesSurfaceFunction(const std::string& glsl) {
  auto isIdent = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (size_t at = glsl.find("surface"); at != std::string::npos; at = glsl.find("surface", at + 1)) {
    size_t end = at + 7;
    if ((at > 0 && isIdent(glsl[at - 1])) || (end < glsl.size() && isIdent(glsl[end]))) continue;
    size_t i = end;
    while (i < glsl.size() && std::isspace(static_cast<unsigned char>(glsl[i]))) ++i;
    if (i >= glsl.size() || glsl[i] != '(') continue;
    size_t j = at;
    while (j > 0 && std::isspace(static_cast<unsigned char>(glsl[j - 1]))) --j;
    if (j >= 4 && j < at && glsl.compare(j - 4, 4, "void") == 0 && (j == 4 || !isIdent(glsl[j - 5]))) return true;
  }
  return false;
}

// Trailing whitespace is not part of the code: both forms then carry identical text.
std::string normalizedSurface(const std::string& glsl) {
  size_t end = glsl.find_last_not_of(" \t\r\n");
  return end == std::string::npos ? std::string() : glsl.substr(0, end + 1) + "\n";
}

class Resolver {
 public:
  Resolver(const MaterialSource& src, const ShaderLibrary& lib, DiagnosticSink& sink)
      : src_(src), lib_(lib), sink_(sink) {}

  MaterialDesc run() {
    desc_.form = src_.form;
    desc_.sourceFile = src_.file;
    desc_.includedFiles = src_.includedFiles;
    desc_.description = src_.description;
    desc_.engine = src_.engine;
    desc_.warnings = src_.warnings;
    resolveName();
    model_ = resolveModel();
    if (model_) resolveFeatures();
    resolveSurface();
    resolveBricks();
    if (model_) resolveLightMethods();
    if (model_) resolveParams();
    if (model_) checkSurfaceNames();
    return desc_;
  }

 private:
  void error(std::string code, const SourceLocation& where, std::string message, std::string suggestion = {}) {
    sink_.error(std::move(code), where, std::move(message), std::move(suggestion));
  }

  // Not written at all (as opposed to written empty): the form has reported it.
  static bool absent(const SourceName& n) { return n.value.empty() && n.where.file.empty(); }

  void resolveName() {
    const std::string& name = src_.name.value;
    if (absent(src_.name)) return;  // the form reported it missing
    if (!isIdentifier(name)) {
      // The name becomes part of GLSL entry points, C++ struct names and file names.
      error("E-INVALID-NAME", src_.name.where,
            "material name '" + clipped(name) + "' must match [A-Za-z_][A-Za-z0-9_]*");
      return;
    }
    desc_.name = name;
  }

  const ShadingModel* resolveModel() {
    const std::string& name = src_.model.value;
    if (absent(src_.model)) return nullptr;
    const ShadingModel* model = lib_.findModel(name);
    if (!model) {
      std::vector<std::string> known;
      for (const auto& m : lib_.models()) known.push_back(m.name);
      error("E-UNKNOWN-MODEL", src_.model.where,
            "unknown shading model '" + clipped(name) + "': the library has " + quotedList(known),
            suggest(name, known));
      return nullptr;
    }
    desc_.model = model->name;
    desc_.modelWhere = src_.model.where;
    return model;
  }

  void resolveFeatures() {
    std::vector<std::string> known, enabled;
    for (const auto& f : model_->features) known.push_back(f.name);
    std::map<std::string, SourceLocation> first;
    for (const auto& f : src_.features) {
      if (!model_->findFeature(f.value)) {
        error("E-UNKNOWN-FEATURE", f.where,
              "unknown feature '" + clipped(f.value) + "': model '" + model_->name + "' has " + quotedList(known),
              suggest(f.value, known));
      } else if (!first.emplace(f.value, f.where).second) {
        error("E-DUPLICATE-NAME", f.where,
              "feature '" + f.value + "' is enabled twice (first at " + at(first[f.value]) + ")");
      } else {
        enabled.push_back(f.value);
      }
    }
    for (const auto& f : known)  // the model's order, so equal materials compare equal
      if (contains(enabled, f)) desc_.features.push_back(f);
  }

  void resolveSurface() {
    if (!src_.surface.present()) return;
    std::string glsl = normalizedSurface(src_.surface.glsl);
    if (glsl.empty()) return;
    if (!definesSurfaceFunction(glsl)) {
      error("E-SURFACE-FUNCTION", src_.surface.where,
            "surface code must define 'void surface(inout MaterialInputs m, MaterialParams p)'");
    }
    desc_.surface.glsl = std::move(glsl);
    desc_.surface.where = src_.surface.where;
  }

  static std::string at(const SourceLocation& l) {
    return l.file + ":" + std::to_string(l.line) + ":" + std::to_string(l.column);
  }

  // --- bricks ---------------------------------------------------------------------------

  // Roles this material has: those without a feature, or whose feature it enables. Light- and
  // environment-conditional roles are included: which permutations need them is issue 5's.
  std::vector<const ModelRole*> activeRoles() const {
    std::vector<const ModelRole*> out;
    for (const auto& r : model_->roles)
      if (r.feature.empty() || desc_.has(r.feature)) out.push_back(&r);
    return out;
  }

  std::vector<std::string> activeRoleNames() const {
    std::vector<std::string> out;
    for (const ModelRole* r : activeRoles()) out.push_back(r->role);
    return out;
  }

  void resolveBricks() {
    std::map<std::string, SourceLocation> seen;
    for (const auto& [role, id] : src_.bricks) {
      if (!seen.emplace(role.value, role.where).second) {
        error("E-DUPLICATE-NAME", role.where,
              "role '" + role.value + "' is given twice (first at " + at(seen[role.value]) + ")");
        continue;
      }
      if (!model_) {
        checkWithoutModel(role, id);
        continue;
      }
      const ModelRole* r = model_->findRole(role.value);
      if (!r) {
        reportUnknownRole(role);
        continue;
      }
      if (!r->feature.empty() && !desc_.has(r->feature)) {
        error("E-FEATURE-DISABLED", role.where,
              "role '" + r->role + "' needs feature '" + r->feature + "' of model '" + model_->name +
                  "': enable the feature or remove the role");
        continue;
      }
      if (checkBrick(id, r->slot)) {
        desc_.bricks[r->role] = id.value;
        desc_.brickLocations[r->role] = id.where;
      }
    }
    if (!model_ || src_.bricksIncomplete) return;
    SourceLocation missingAt = src_.bricksWhere.file.empty() ? src_.model.where : src_.bricksWhere;
    for (const ModelRole* r : activeRoles()) {
      if (seen.count(r->role)) continue;
      if (!r->defaultBrick.empty()) {
        desc_.bricks[r->role] = r->defaultBrick;
        continue;
      }
      error("E-MISSING-FIELD", missingAt,
            "bricks is missing role '" + r->role + "' (slot '" + r->slot + "') of model '" + model_->name +
                "': choose one of " + quotedList(lib_.bricksOfSlot(r->slot)));
    }
  }

  // Each light the model offers methods for gets the material's choice, else the default
  // (a quality level may replace a default, never a choice: permute/specialize.cpp).
  void resolveLightMethods() {
    std::vector<std::string> lights;
    for (const auto& c : model_->lightMethods) lights.push_back(lightTypeName(c.light));
    std::map<std::string, SourceLocation> seen;
    for (const auto& [light, method] : src_.lightMethods) {
      if (!seen.emplace(light.value, light.where).second) {
        error("E-DUPLICATE-NAME", light.where,
              "light '" + clipped(light.value) + "' is given a method twice (first at " + at(seen[light.value]) + ")");
        continue;
      }
      auto type = parseLightType(light.value);
      const LightMethodChoice* choice = type ? model_->findLightMethod(*type) : nullptr;
      if (!choice) {
        error("E-UNKNOWN-NAME", light.where,
              "model '" + model_->name + "' offers no methods for light '" + clipped(light.value) + "': it does for " +
                  quotedList(lights),
              suggest(light.value, lights));
        continue;
      }
      if (!contains(choice->methods, method.value)) {
        error("E-UNKNOWN-NAME", method.where,
              "unknown method '" + clipped(method.value) + "' for " + light.value + " lights: expected one of " +
                  quotedList(choice->methods),
              suggest(method.value, choice->methods));
        continue;
      }
      desc_.lightMethods[light.value] = method.value;
      desc_.lightMethodLocations[light.value] = method.where;
    }
    for (const auto& c : model_->lightMethods) desc_.lightMethods.emplace(lightTypeName(c.light), c.defaultMethod);
  }

  // Without a known model only the brick ids can be checked (and their slot, when the key
  // happens to be a slot name): roles are the model's.
  void checkWithoutModel(const SourceName& role, const SourceName& id) {
    if (lib_.findSlot(role.value)) {
      checkBrick(id, role.value);
    } else if (!lib_.findBrick(id.value)) {
      error("E-UNKNOWN-BRICK", id.where, "unknown brick '" + clipped(id.value) + "'",
            suggest(id.value, lib_.brickIds()));
    }
  }

  void reportUnknownRole(const SourceName& role) {
    std::vector<std::string> roles = activeRoleNames();
    std::string message = lib_.findSlot(role.value)
                              ? "slot '" + role.value + "' is not used by model '" + model_->name +
                                    "' (its slots are " + quotedList(roles) + ")"
                              : "unknown slot '" + clipped(role.value) + "': expected one of " + quotedList(roles);
    error("E-UNKNOWN-SLOT", role.where, message, suggest(role.value, roles));
  }

  // True if `id` names a brick of `slot`; otherwise reports why not.
  bool checkBrick(const SourceName& id, const std::string& slot) {
    std::vector<std::string> ofSlot = lib_.bricksOfSlot(slot);
    const Brick* brick = lib_.findBrick(id.value);
    if (!brick) {
      // Prefer suggestions that fit the slot; fall back to any brick (wrong slot is a
      // separate, clearer error once the user picks it).
      std::string suggestion = suggest(id.value, ofSlot);
      if (suggestion.empty()) suggestion = suggest(id.value, lib_.brickIds());
      error("E-UNKNOWN-BRICK", id.where,
            "unknown brick '" + clipped(id.value) + "' for slot '" + slot + "': expected one of " + quotedList(ofSlot),
            suggestion);
      return false;
    }
    if (brick->slot != slot) {
      error("E-BRICK-WRONG-SLOT", id.where,
            "brick '" + id.value + "' fills slot '" + brick->slot + "', expected a '" + slot + "' brick: one of " +
                quotedList(ofSlot));
      return false;
    }
    return true;
  }

  // --- parameters -----------------------------------------------------------------------

  void resolveParams() {
    std::map<std::string, MaterialParam> given;
    std::vector<MaterialParam> user;
    std::map<std::string, SourceLocation> seen;
    for (const auto& sp : src_.params) {
      if (!seen.emplace(sp.name, sp.where).second) {
        error("E-DUPLICATE-NAME", sp.where,
              "parameter '" + sp.name + "' is given twice (first at " + at(seen[sp.name]) + ")");
        continue;
      }
      auto input = std::find_if(model_->inputs.begin(), model_->inputs.end(),
                                [&](const ModelInput& in) { return in.name == sp.name; });
      if (input != model_->inputs.end()) {
        if (!input->feature.empty() && !desc_.has(input->feature)) {
          error("E-FEATURE-DISABLED", sp.where,
                "input '" + sp.name + "' belongs to feature '" + input->feature + "' of model '" + model_->name +
                    "': enable the feature or remove the parameter");
        } else if (auto p = modelParam(sp, *input)) {
          given[sp.name] = *p;
        }
      } else if (desc_.surface.present()) {
        if (auto p = userParam(sp)) user.push_back(*p);
      } else {
        reportUnknownParam(sp);
      }
    }
    // Model inputs in the model's order, so the emitted struct is stable; then user ones.
    for (const auto& in : model_->inputs) {
      if (!in.feature.empty() && !desc_.has(in.feature)) continue;
      auto it = given.find(in.name);
      desc_.params.push_back(it != given.end() ? it->second : defaultParam(in));
    }
    desc_.params.insert(desc_.params.end(), user.begin(), user.end());
  }

  void reportUnknownParam(const SourceParam& sp) {
    std::vector<std::string> active, all;
    for (const auto& in : model_->inputs) {
      all.push_back(in.name);
      if (in.feature.empty() || desc_.has(in.feature)) active.push_back(in.name);
    }
    error("E-UNKNOWN-FIELD", sp.where,
          "unknown parameter '" + clipped(sp.name) + "': model '" + model_->name + "' has inputs " +
              quotedList(active) + " (a parameter that is not a model input needs surface code)",
          suggest(sp.name, all));
  }

  // Inputs a material does not mention are folded in as constants at the model's default.
  MaterialParam defaultParam(const ModelInput& in) const {
    MaterialParam p;
    p.name = in.name;
    p.type = in.type;
    p.value = in.defaultValue;
    p.constant = true;
    p.range = in.range;
    p.where = src_.model.where;  // the value comes from the model
    return p;
  }

  // How messages name a part of a parameter: JSON paths for JSON, the name otherwise.
  std::string label(const SourceParam& sp, const std::string& part, int component = -1) const {
    std::string s =
        src_.form == "json" ? "parameters." + sp.name + "." + part : sp.name + (part == "default" ? "" : " " + part);
    if (component >= 0) s += "[" + std::to_string(component) + "]";
    return "'" + s + "'";
  }

  std::optional<MaterialParam> modelParam(const SourceParam& sp, const ModelInput& in) {
    bool ok = !sp.incomplete;
    bool typeOk = true;
    if (sp.type) {
      auto declared = declaredType(sp);
      if (declared && *declared != in.type) {
        error("E-PARAM-TYPE", sp.typeWhere,
              "parameter '" + sp.name + "' is declared '" + *sp.type + "' but model input '" + in.name + "' is a " +
                  toString(in.type));
      }
      typeOk = declared == in.type;
    }
    std::optional<Range> own = ownRange(sp);
    if (own && (own->lo < in.range.lo || own->hi > in.range.hi)) {
      error("E-PARAM-RANGE", sp.rangeWhere,
            label(sp, "range") + " " + formatRange(*own) + " must lie inside the range " + formatRange(in.range) +
                " of model input '" + in.name + "'");
      own.reset();
      ok = false;
    }
    if (sp.range && !own) ok = false;
    // A broken own range is already reported; the model's range still catches a bad default.
    Range range = own.value_or(in.range);
    std::string origin = own ? "the parameter's range" : "the range of model input '" + in.name + "'";
    // A value written for the declared type would only repeat the type error in other words.
    bool valueOk = sp.value.size() != static_cast<size_t>(componentCount(in.type)) && !typeOk
                       ? false
                       : checkValue(sp, in.type, range, origin);
    if (!ok || !typeOk || !valueOk) return std::nullopt;
    return param(sp, in.type, range, false);
  }

  std::optional<MaterialParam> userParam(const SourceParam& sp) {
    bool ok = !sp.incomplete;
    if (!isIdentifier(sp.name)) {
      error("E-INVALID-NAME", sp.where, "parameter name '" + clipped(sp.name) + "' must match [A-Za-z_][A-Za-z0-9_]*");
      return std::nullopt;
    }
    std::string reserved = reservedNameReason(sp.name, generatedNames());
    if (!reserved.empty()) {
      error("E-INVALID-NAME", sp.where, "parameter name '" + sp.name + "' is " + reserved);
      ok = false;
    }
    std::optional<ValueType> type;
    if (!sp.type) {
      if (!sp.incomplete)
        error("E-MISSING-FIELD", sp.where, "user parameter '" + sp.name + "' needs a type: 'float', 'vec2' or 'vec3'");
      return std::nullopt;
    }
    type = declaredType(sp);
    if (!type) return std::nullopt;
    std::optional<Range> own = ownRange(sp);
    const bool brokenRange = sp.range && !own;
    if (brokenRange) ok = false;
    // A broken range is already reported: the default is then only held to fp32.
    Range range = own.value_or(brokenRange ? Range{-FLT_MAX, FLT_MAX} : kUserDefaultRange);
    std::string origin = own           ? "the parameter's range"
                         : brokenRange ? "the fp32 range"
                                       : "the default range [0, 1] of a user parameter (give it a range)";
    ok = checkValue(sp, *type, range, origin) && ok;
    if (!ok) return std::nullopt;
    return param(sp, *type, range, true);
  }

  // A global name of the surface code that the generated code uses after it (a function or
  // macro of the same name) would fail in glslang at a generated line: refused at the user's.
  void checkSurfaceNames() {
    if (!desc_.surface.present()) return;
    for (const DeclaredName& d : globalNamesOf(desc_.surface.glsl)) {
      if (d.name == "surface") continue;
      auto it = generatedNames().find(d.name);
      // A macro rewrites every later use; a function, struct or variable only clashes with a
      // global (a generated local shadows it).
      if (it == generatedNames().end() || (!d.macro && it->second.localOnly)) continue;
      SourceLocation where = desc_.surface.where;
      where.column = d.line == 0 ? std::max(1, where.column) + d.column - 1 : d.column;
      where.line = std::max(1, where.line) + d.line;
      error("E-INVALID-NAME", where,
            "surface code declares '" + d.name + "', which is already used by the generated code (" + it->second.what +
                ")");
    }
  }

  // What the code emitted for this material (its model, features and bricks) names, derived
  // once per material and only when it has a user parameter to check.
  const std::map<std::string, GeneratedName>& generatedNames() {
    if (!generated_) generated_ = generatedNamesOf(lib_, desc_);
    return *generated_;
  }

  // The declared type, if it is one of ours; otherwise reports it.
  std::optional<ValueType> declaredType(const SourceParam& sp) {
    const std::vector<std::string> allowed = {"float", "vec2", "vec3"};
    if (!contains(allowed, *sp.type)) {
      error("E-PARAM-TYPE", sp.typeWhere,
            "unknown parameter type '" + clipped(*sp.type) + "': expected one of " + quotedList(allowed),
            suggest(*sp.type, allowed));
      return std::nullopt;
    }
    return parseValueType(*sp.type);
  }

  // The range as written, if it is one (a form may hand over lo > hi).
  std::optional<Range> ownRange(const SourceParam& sp) {
    if (!sp.range) return std::nullopt;
    if (!(sp.range->lo <= sp.range->hi) || !std::isfinite(sp.range->lo) || !std::isfinite(sp.range->hi)) {
      error("E-PARAM-RANGE", sp.rangeWhere,
            label(sp, "range") + " is an empty range: lo " + formatNumber(sp.range->lo) + " > hi " +
                formatNumber(sp.range->hi));
      return std::nullopt;
    }
    // Every value becomes an fp32 literal or uniform: a bound beyond fp32 (a double JSON or
    // the macro form accepts, 1e39) would make an infinite range the sampler cannot draw from.
    if (!fitsFloat(sp.range->lo) || !fitsFloat(sp.range->hi)) {
      error("E-PARAM-RANGE", sp.rangeWhere,
            label(sp, "range") + " " + formatRange(*sp.range) + " reaches beyond the fp32 range [" +
                formatNumber(-FLT_MAX) + ", " + formatNumber(FLT_MAX) + "]");
      return std::nullopt;
    }
    return sp.range;
  }

  static bool fitsFloat(double v) { return std::fabs(v) <= FLT_MAX; }

  // The value's count of numbers fits `type` and every number lies in `range`.
  bool checkValue(const SourceParam& sp, ValueType type, const Range& range, const std::string& origin) {
    if (sp.value.empty()) return false;  // the form reported it
    size_t n = static_cast<size_t>(componentCount(type));
    if (sp.value.size() != n) {
      error("E-PARAM-TYPE", sp.valueWhere,
            label(sp, "default") + " must be a " + toString(type) + " (" + std::to_string(n) +
                (n == 1 ? " number" : " numbers") + "), found " + std::to_string(sp.value.size()));
      return false;
    }
    bool ok = true;
    for (size_t i = 0; i < n; ++i) {
      if (std::isfinite(sp.value[i]) && sp.value[i] >= range.lo && sp.value[i] <= range.hi) continue;
      // Point at the offending component of a vector, so the column is exact.
      bool vec = n > 1;
      SourceLocation where = vec && i < sp.componentWhere.size() ? sp.componentWhere[i] : sp.valueWhere;
      const std::string what = label(sp, "default", vec ? static_cast<int>(i) : -1) + " = " + formatNumber(sp.value[i]);
      if (std::isfinite(sp.value[i]) && !fitsFloat(sp.value[i]))
        error("E-PARAM-RANGE", where,
              what + " is beyond the fp32 range [" + formatNumber(-FLT_MAX) + ", " + formatNumber(FLT_MAX) +
                  "] of the shader's value");
      else
        error("E-PARAM-RANGE", where, what + " is outside " + formatRange(range) + ", " + origin);
      ok = false;
    }
    return ok;
  }

  MaterialParam param(const SourceParam& sp, ValueType type, const Range& range, bool user) const {
    MaterialParam p;
    p.name = sp.name;
    p.type = type;
    p.value = sp.value;
    p.constant = sp.constant;
    p.range = range;
    p.user = user;
    p.where = sp.where;
    return p;
  }

  const MaterialSource& src_;
  const ShaderLibrary& lib_;
  DiagnosticSink& sink_;
  const ShadingModel* model_ = nullptr;
  MaterialDesc desc_;
  std::optional<std::map<std::string, GeneratedName>> generated_;
};

}  // namespace

MaterialDesc resolveMaterialInto(const MaterialSource& source, const ShaderLibrary& lib, DiagnosticSink& sink) {
  return Resolver(source, lib, sink).run();
}

void throwInFileOrder(const DiagnosticSink& sink, const std::string& mainFile) {
  if (!sink.hasErrors()) return;
  std::vector<Diagnostic> diags = sink.all();
  std::map<std::string, size_t> rank{{mainFile, 0}};
  for (const auto& d : diags) rank.emplace(d.where.file, rank.size());
  std::stable_sort(diags.begin(), diags.end(), [&](const Diagnostic& a, const Diagnostic& b) {
    return std::make_tuple(rank[a.where.file], a.where.line, a.where.column) <
           std::make_tuple(rank[b.where.file], b.where.line, b.where.column);
  });
  throw DiagnosticError(std::move(diags));
}

MaterialDesc finishMaterial(const MaterialSource& source, const ShaderLibrary& lib, DiagnosticSink& sink) {
  MaterialDesc desc = resolveMaterialInto(source, lib, sink);
  throwInFileOrder(sink, source.file);
  return desc;
}

MaterialDesc resolveMaterial(const MaterialSource& source, const ShaderLibrary& lib) {
  DiagnosticSink sink;
  MaterialDesc desc = finishMaterial(source, lib, sink);
  for (const auto& d : sink.all()) desc.warnings.push_back(d);  // warnings only, by now
  return desc;
}

}  // namespace mb
