#include "stress/stress_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mb {
namespace {

nlohmann::json number(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");  // JSON has no NaN/Inf
}

// "col=value,..." for one row, as validate's worst_input.
std::string inlineRow(const std::vector<std::string>& cols, const std::vector<float>& row) {
  std::string s;
  char buf[32];
  for (size_t k = 0; k < row.size() && k < cols.size(); ++k) {
    std::snprintf(buf, sizeof buf, "%.9g", row[k]);
    s += (k ? "," : "") + cols[k] + "=" + buf;
  }
  return s;
}

nlohmann::json statsJson(const StressStats& s) {
  return {{"records", s.records},
          {"values", s.values},
          {"nan_count", s.nanCount},
          {"inf_count", s.infCount},
          {"negative_count", s.negativeCount},
          {"reference_undefined_count", s.referenceUndefined},
          {"overflow_count", s.overflowCount},
          {"max_abs_error", number(s.maxAbs)},
          {"max_rel_error", number(s.maxRel)}};
}

std::string shellEscapeNewlines(const std::string& csv) {
  std::string out;
  for (char c : csv) out += c == '\n' ? std::string("\\n") : std::string(1, c);
  return out;
}

}  // namespace

std::string replayCommand(const StressResult& r, const std::string& cli, bool inDomain) {
  const std::vector<float>& row = inDomain ? r.worstInDomainRow : r.worstOutOfDomainRow;
  if (row.empty()) return "";
  std::string file = r.key + (inDomain ? "" : ".out_of_domain") + ".worst.csv";
  std::string what = r.kind == "brick"
                         ? "--brick " + r.id
                         : "--material " + r.id + (r.materialName.empty() ? "" : " --name " + r.materialName);
  std::string precision = r.precision != ShaderPrecision::Fp16 ? ""
                          : r.fp16Mode == Fp16Mode::Driver     ? " --precision fp16 --fp16 driver"
                                                               : " --precision fp16";
  return "printf '" + shellEscapeNewlines(csvRow(r.columns, row)) + "' > " + file + " && " + cli + " eval " + what +
         precision + " --input " + file;
}

nlohmann::json toJson(const StressResult& r, const std::string& cli) {
  nlohmann::json j{{"key", r.key},
                   {"kind", r.kind},
                   {"id", r.id},
                   {"material", r.kind == "brick" ? nlohmann::json(nullptr) : nlohmann::json(r.materialName)},
                   {"precision", precisionName(r.precision)},
                   {"fp16", r.precision == ShaderPrecision::Fp16 ? nlohmann::json(fp16ModeName(r.fp16Mode))
                                                                 : nlohmann::json(nullptr)},
                   {"passed", r.passed()}};
  if (!r.compileError.empty()) {
    j["compile_error"] = r.compileError;
    return j;
  }
  j["in_domain"] = statsJson(r.inDomain);
  j["out_of_domain"] = statsJson(r.outOfDomain);
  if (!r.worstInDomainRow.empty()) {
    j["in_domain"]["worst_input"] = inlineRow(r.columns, r.worstInDomainRow);
    j["in_domain"]["worst_csv"] = csvRow(r.columns, r.worstInDomainRow);
    j["in_domain"]["worst_gpu"] = nlohmann::json::array();
    for (double v : r.worstInDomainGpu) j["in_domain"]["worst_gpu"].push_back(number(v));
    j["in_domain"]["worst_reference"] = nlohmann::json::array();
    for (double v : r.worstInDomainReference) j["in_domain"]["worst_reference"].push_back(number(v));
    j["in_domain"]["replay"] = replayCommand(r, cli, true);
  }
  if (!r.worstOutOfDomainRow.empty()) {
    j["out_of_domain"]["worst_input"] = inlineRow(r.columns, r.worstOutOfDomainRow);
    j["out_of_domain"]["worst_csv"] = csvRow(r.columns, r.worstOutOfDomainRow);
    j["out_of_domain"]["replay"] = replayCommand(r, cli, false);
  }
  return j;
}

std::string formatStressTable(const std::vector<StressResult>& results) {
  std::ostringstream s;
  char line[512];
  std::snprintf(line, sizeof line, "%-48s %8s %5s %5s %6s %6s %5s %10s %10s | %8s %5s %5s %6s  %s\n", "probe",
                "in_recs", "nan", "inf", "neg", "undef", "ovf", "max_abs", "max_rel", "out_recs", "nan", "inf", "undef",
                "result");
  s << line;
  for (const auto& r : results) {
    if (!r.compileError.empty()) {
      s << r.key << "  DOES NOT BUILD: " << r.compileError << "\n";
      continue;
    }
    const StressStats &in = r.inDomain, &out = r.outOfDomain;
    auto u = [](uint64_t v) { return static_cast<unsigned long long>(v); };
    std::snprintf(line, sizeof line,
                  "%-48s %8llu %5llu %5llu %6llu %6llu %5llu %10.3g %10.3g | %8llu %5llu %5llu %6llu  %s\n",
                  r.key.c_str(), u(in.records), u(in.nanCount), u(in.infCount), u(in.negativeCount),
                  u(in.referenceUndefined), u(in.overflowCount), in.maxAbs, in.maxRel, u(out.records), u(out.nanCount),
                  u(out.infCount), u(out.referenceUndefined), r.passed() ? "PASS" : "FAIL");
    s << line;
  }
  return s.str();
}

std::string formatStressMarkdown(const std::vector<StressResult>& results, const std::string& command,
                                 const std::string& device) {
  std::ostringstream s;
  const char* p = results.empty() ? "fp32" : precisionName(results.front().precision);
  const bool half = !results.empty() && results.front().precision == ShaderPrecision::Fp16;
  const bool emulated = half && results.front().fp16Mode == Fp16Mode::Emulated;
  s << "# " << p << " error of every brick against its double reference\n\n"
    << "Generated by `" << command << "`; do not edit by hand. Device: " << device << ".\n\n"
    << "Each brick runs with "
    << (!half      ? "fp32 arithmetic"
        : emulated ? "fp16 arithmetic as the least precise conforming Vulkan device may compute it (`--fp16 "
                     "emulated`: every half result rounded, denormals both flushed and kept, division by the "
                     "reciprocal, transcendentals at the edge of the spec's error bounds; what this models and "
                     "what it cannot: [docs/stress.md](stress.md#the-fp16-emulation))"
                   : "the device's own fp16 arithmetic (`--fp16 driver`)")
    << " over the adversarial stress set plus 1024 validation samples "
       "([docs/stress.md](stress.md)); the reference stays double. Columns count in-domain "
       "values (the "
    << p
    << " domain: at fp16 roughness-like inputs start at 0.089, alpha at "
       "0.089^2, and vectors have unit length); max rel uses a floor of 1e-6 on |reference|. "
       "`undef` counts inputs where the reference itself is not finite, `ovf` Inf results whose "
       "exact value exceeds the largest finite value (65504 in half; IEEE rounding gives Inf). "
       "Out-of-domain NaN/Inf "
       "are shown for information only. The worst input is the first NaN/Inf, else the largest "
       "relative error, as `eval` columns. Guards added and open findings: "
       "[docs/stress.md](stress.md#fp16-findings).\n\n"
    << "| brick or permutation | values | NaN | Inf | neg | undef | ovf | max abs | max rel | out-of-domain NaN/Inf | worst in-domain input |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[64];
  for (const auto& r : results) {
    std::string id = r.kind == "brick" ? r.id : r.key;
    if (!r.compileError.empty()) {
      s << "| `" << id << "` | does not build at " << p << " | | | | | | | | | |\n";
      continue;
    }
    const StressStats &in = r.inDomain, &out = r.outOfDomain;
    s << "| `" << id << "` | " << in.values << " | " << in.nanCount << " | " << in.infCount << " | " << in.negativeCount
      << " | " << in.referenceUndefined << " | " << in.overflowCount << " | ";
    std::snprintf(buf, sizeof buf, "%.3g | %.3g", in.maxAbs, in.maxRel);
    s << buf << " | " << out.nanCount << "/" << out.infCount << " | `" << inlineRow(r.columns, r.worstInDomainRow)
      << "` |\n";
  }
  return s.str();
}

}  // namespace mb
