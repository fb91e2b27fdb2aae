// Material JSON -> MaterialSource -> resolveMaterial (format: docs/formats.md, "Material JSON").
// This file checks only what is JSON about a material (keys, JSON types, the shape of values);
// what the material means is checked by resolveMaterial, shared with the macro form and glTF.
// Both report into one sink, so every problem of a file comes out at once, in file order.
#include <algorithm>
#include <optional>
#include <tuple>

#include "core/json_fields.hpp"
#include "library/value_json.hpp"
#include "load/material_desc.hpp"
#include "load/material_resolve.hpp"
#include "load/project_files.hpp"

namespace mb {

using nlohmann::json;

namespace {

// A material is at most 4 levels deep: anything past 64 is refused by JsonDocument::parse
// before its recursive position scanner runs.
constexpr int kMaxMaterialJsonDepth = 64;
// A material has tens of values (a few hundred with many parameters); 16 MiB of tiny ones
// would build a tree of ~10 bytes per input byte for nothing (docs/formats.md "Input files").
constexpr size_t kMaxMaterialJsonValues = 100'000;

class JsonMaterialReader {
 public:
  JsonMaterialReader(const JsonDocument& doc, const ShaderLibrary& lib, DiagnosticSink& sink)
      : doc_(doc), lib_(lib), f_(doc, sink) {}

  MaterialSource run() {
    src_.file = doc_.file();
    src_.form = "json";
    src_.bricksIncomplete = true;
    if (!f_.object("", {"name", "model", "bricks"},
                   {"description", "features", "parameters", "surface", "lightMethods"}, "material"))
      return src_;
    src_.name = name("/name");
    src_.model = name("/model");
    src_.description = f_.string("/description").value_or("");
    readFeatures();
    readBricks();
    readLightMethods();
    if (f_.find("/surface")) readSurface();
    if (f_.isObject("/parameters"))
      for (const auto& key : keysInFileOrder("/parameters")) readParam(key);
    return src_;
  }

 private:
  SourceName name(const std::string& ptr) {
    auto s = f_.string(ptr);
    if (!s) return {};  // absent (reported by object()) or not a string (reported by string())
    return {*s, f_.valueAt(ptr)};
  }

  // nlohmann iterates object members alphabetically; materials keep the author's order.
  std::vector<std::string> keysInFileOrder(const std::string& ptr) const {
    std::vector<std::string> keys;
    for (const auto& item : f_.find(ptr)->items()) keys.push_back(item.key());
    auto pos = [&](const std::string& k) {
      SourceLocation l = f_.keyAt(JsonFields::member(ptr, k));
      return std::make_pair(l.line, l.column);
    };
    std::stable_sort(keys.begin(), keys.end(),
                     [&](const std::string& a, const std::string& b) { return pos(a) < pos(b); });
    return keys;
  }

  void readFeatures() {
    if (!f_.isArray("/features")) return;
    for (size_t i = 0; i < f_.find("/features")->size(); ++i) {
      SourceName n = name(JsonFields::element("/features", i));
      if (!n.where.file.empty()) src_.features.push_back(n);
    }
  }

  void readBricks() {
    if (!f_.isObject("/bricks")) return;
    src_.bricksIncomplete = false;
    src_.bricksWhere = f_.valueAt("/bricks");
    for (const auto& role : keysInFileOrder("/bricks")) {
      std::string ptr = JsonFields::member("/bricks", role);
      SourceName id = name(ptr);
      if (id.where.file.empty()) {
        src_.bricksIncomplete = true;  // not a string: reported
        continue;
      }
      src_.bricks.push_back({SourceName{role, f_.keyAt(ptr)}, id});
    }
  }

  // "lightMethods": {"sphere": "representative_point"} (docs/formats.md "Material JSON").
  void readLightMethods() {
    if (!f_.isObject("/lightMethods")) return;
    for (const auto& light : keysInFileOrder("/lightMethods")) {
      std::string ptr = JsonFields::member("/lightMethods", light);
      SourceName method = name(ptr);
      if (!method.where.file.empty()) src_.lightMethods.push_back({SourceName{light, f_.keyAt(ptr)}, method});
    }
  }

  // {"file": "velvet.surface.glsl"} (relative to this file, inside its directory) or
  // {"glsl": "..."} (its lines are the string's \n-separated lines, the first on the
  // string's own line).
  void readSurface() {
    if (!f_.object("/surface", {}, {"file", "glsl"}, "surface")) return;
    bool hasFile = f_.find("/surface/file") != nullptr, hasGlsl = f_.find("/surface/glsl") != nullptr;
    if (hasFile == hasGlsl) {
      f_.error(hasFile ? "E-CONFLICTING-FIELDS" : "E-MISSING-FIELD", f_.valueAt("/surface"),
               hasFile ? "surface has both 'file' and 'glsl': give one of them"
                       : "surface needs 'file' (a GLSL file) or 'glsl' (the code as a string)");
      return;
    }
    if (hasGlsl) {
      auto glsl = f_.string("/surface/glsl");
      if (!glsl) return;
      SourceLocation where = f_.valueAt("/surface/glsl");
      ++where.column;  // past the opening quote
      src_.surface = {*glsl, where};
      return;
    }
    auto written = f_.string("/surface/file");
    if (!written) return;
    ProjectFiles project(doc_.file());
    auto path = project.resolve(*written, doc_.file(), f_.valueAt("/surface/file"), f_.sink());
    if (!path) return;
    auto text = readTextFile(*path, f_.valueAt("/surface/file"), input_kind::kSurface, f_.sink());
    if (text) src_.surface = {*text, SourceLocation(*path, 1, 1)};
  }

  // The type the default must have: the model input's (authoritative), else the declared one.
  std::optional<ValueType> expectedType(const SourceParam& sp) const {
    if (const ShadingModel* m = lib_.findModel(src_.model.value))
      for (const auto& in : m->inputs)
        if (in.name == sp.name) return in.type;
    if (sp.type && (*sp.type == "float" || *sp.type == "vec2" || *sp.type == "vec3")) return parseValueType(*sp.type);
    return std::nullopt;
  }

  // A number or an array of numbers, for a default whose type is unknown.
  std::optional<std::vector<double>> numbers(const std::string& ptr) {
    const json* j = f_.find(ptr);
    if (j->is_number()) return std::vector<double>{j->get<double>()};
    if (j->is_array() && !j->empty() && std::all_of(j->begin(), j->end(), [](const json& c) { return c.is_number(); }))
      return j->get<std::vector<double>>();
    f_.error(
        "E-PARAM-TYPE", f_.valueAt(ptr),
        "'" + JsonFields::describe(ptr) + "' must be a number or an array of numbers, found " + JsonFields::kindOf(*j));
    return std::nullopt;
  }

  void readParam(const std::string& key) {
    std::string ptr = JsonFields::member("/parameters", key);
    if (!f_.object(ptr, {"type", "default"}, {"range", "constant"}, "parameter '" + clipped(key) + "'")) return;
    SourceParam sp;
    sp.name = key;
    sp.where = f_.keyAt(ptr);
    sp.incomplete = !f_.find(ptr + "/type") || !f_.find(ptr + "/default");
    if (f_.find(ptr + "/type")) {
      auto t = f_.string(ptr + "/type");
      if (t)
        sp.type = *t;
      else
        sp.incomplete = true;
      sp.typeWhere = f_.valueAt(ptr + "/type");
    }
    if (f_.find(ptr + "/default")) {
      std::string at = ptr + "/default";
      auto expected = expectedType(sp);
      auto value = expected ? readTypedValue(f_, at, *expected) : numbers(at);
      sp.valueWhere = f_.valueAt(at);
      if (value) {
        sp.value = *value;
        if (f_.find(at)->is_array())
          for (size_t i = 0; i < value->size(); ++i)
            sp.componentWhere.push_back(f_.valueAt(JsonFields::element(at, i)));
      } else {
        sp.incomplete = true;
      }
    }
    if (f_.find(ptr + "/range")) {
      sp.rangeWhere = f_.valueAt(ptr + "/range");
      if (auto r = f_.range(ptr + "/range")) sp.range = Range{r->first, r->second};
    }
    if (f_.find(ptr + "/constant")) {
      auto c = f_.boolean(ptr + "/constant");
      if (c)
        sp.constant = *c;
      else
        sp.incomplete = true;
    }
    src_.params.push_back(std::move(sp));
  }

  const JsonDocument& doc_;
  const ShaderLibrary& lib_;
  JsonFields f_;
  MaterialSource src_;
};

}  // namespace

MaterialDesc parseMaterialJson(std::string text, const std::string& file, const ShaderLibrary& lib) {
  JsonDocument doc = JsonDocument::parse(std::move(text), file, kMaxMaterialJsonDepth, kMaxMaterialJsonValues);
  DiagnosticSink sink;
  return finishMaterial(JsonMaterialReader(doc, lib, sink).run(), lib, sink);
}

MaterialDesc loadMaterialJson(const std::string& path, const ShaderLibrary& lib) {
  return parseMaterialJson(readMaterialFile(path, input_kind::kMaterial), path, lib);
}

}  // namespace mb
