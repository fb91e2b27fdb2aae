// The DFG LUT kernel's quadrature rule (lut_kernel.hpp QuadratureRule) evaluated in double
// (lut::evaluateQuadratureRule) against the adaptive references (lut::quadrature) over the
// texel centres of 16^2 and 64^2 tables (every texel) and of 128^2 ... 4096^2 tables (the
// first and last four rows and columns and a 32-per-axis sub-grid): the quadrature error of
// the rule alone, without fp32 rounding. This is how the rule's node counts are chosen: the
// shipped rule is the cheapest of those measured whose error stays below 1/8 of the LUT's
// bounds (docs/lut.md). Prints JSON lines (bench/README.md has the command).
//
//   mb_bench_lut_rule                  the shipped rule, then each count one step cheaper
//   mb_bench_lut_rule key=value...     one rule: the shipped one with those fields changed
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "lut/dfg_lut.hpp"
#include "lut/lut_check.hpp"
#include "lut/lut_kernel.hpp"
#include "lut/lut_reference.hpp"

using namespace mb;

namespace {

struct Texel {
  uint32_t size, i, j;
  std::array<double, lut::kChannels> exact{};
};

std::vector<Texel> texelSet() {
  std::vector<Texel> out;
  for (uint32_t size : {16u, 64u, 128u, 256u, 1024u, 4096u}) {
    std::vector<uint32_t> axis = lut::checkIndices(size, size <= 64 ? 0 : 32);
    if (size > 64)
      for (uint32_t k = 0; k < 4; ++k) axis.push_back(k), axis.push_back(size - 1 - k);
    std::sort(axis.begin(), axis.end());
    axis.erase(std::unique(axis.begin(), axis.end()), axis.end());
    for (uint32_t j : axis)
      for (uint32_t i : axis) out.push_back({size, i, j, {}});
  }
  return out;
}

template <class F>
void parallelFor(size_t n, const F& f) {
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k; (k = next.fetch_add(1)) < n;) f(k);
  };
  std::vector<std::thread> pool(std::max(1u, std::thread::hardware_concurrency()));
  for (auto& th : pool) th = std::thread(worker);
  for (auto& th : pool) th.join();
}

bool setField(lut::QuadratureRule& r, const std::string& key, double v) {
  const int n = static_cast<int>(v);
  if (key == "ggxFullOuter")
    r.ggxFullOuter = n;
  else if (key == "ggxFullInner")
    r.ggxFullInner = n;
  else if (key == "ggxPartialOuter")
    r.ggxPartialOuter = n;
  else if (key == "ggxPartialInner")
    r.ggxPartialInner = n;
  else if (key == "clothOuter")
    r.clothOuter = n;
  else if (key == "clothInner")
    r.clothInner = n;
  else if (key == "ggxPanelWidth")
    r.ggxPanelWidth = v;
  else if (key == "clothPanelWidth")
    r.clothPanelWidth = v;
  else if (key == "ggxBelowPeak")
    r.ggxBelowPeak = v;
  else if (key == "ggxAbovePeak")
    r.ggxAbovePeak = v;
  else if (key == "clothBelowPeak")
    r.clothBelowPeak = v;
  else if (key == "clothAbovePeak")
    r.clothAbovePeak = v;
  else
    return false;
  return true;
}

nlohmann::json measure(const std::string& name, const lut::QuadratureRule& rule, const std::vector<Texel>& texels) {
  std::vector<std::array<double, lut::kChannels>> ratio(texels.size());
  std::vector<long> evaluations(texels.size());
  parallelFor(texels.size(), [&](size_t k) {
    const Texel& t = texels[k];
    const auto r = lut::evaluateQuadratureRule(rule, lut::texelCentre(t.i, t.size), lut::texelCentre(t.j, t.size),
                                               &evaluations[k]);
    for (uint32_t c = 0; c < lut::kChannels; ++c)
      ratio[k][c] = std::fabs(r[c] - t.exact[c]) /
                    (c == lut::kChannelCloth ? lut::kClothRelBound * std::fabs(t.exact[c]) + lut::kClothAbsFloor
                                             : lut::kExactAbsBound);
  });
  nlohmann::json channels = nlohmann::json::object();
  for (uint32_t c = 0; c < lut::kChannels; ++c) {
    size_t worst = 0;
    for (size_t k = 0; k < texels.size(); ++k)
      if (ratio[k][c] > ratio[worst][c]) worst = k;
    channels[lut::kChannelNames[c]] = {
        {"max_error_over_bound", ratio[worst][c]},
        {"at", {{"size", texels[worst].size}, {"i", texels[worst].i}, {"j", texels[worst].j}}}};
  }
  double sum64 = 0;
  long count64 = 0, most = 0;
  for (size_t k = 0; k < texels.size(); ++k) {
    most = std::max(most, evaluations[k]);
    if (texels[k].size == 64) sum64 += evaluations[k], ++count64;
  }
  return {{"rule", name},
          {"counts",
           {{"ggxFullOuter", rule.ggxFullOuter},
            {"ggxFullInner", rule.ggxFullInner},
            {"ggxPartialOuter", rule.ggxPartialOuter},
            {"ggxPartialInner", rule.ggxPartialInner},
            {"clothOuter", rule.clothOuter},
            {"clothInner", rule.clothInner},
            {"ggxPanelWidth", rule.ggxPanelWidth},
            {"clothPanelWidth", rule.clothPanelWidth}}},
          {"channels", channels},
          {"inner_evaluations_per_texel_mean_64", sum64 / std::max(1L, count64)},
          {"inner_evaluations_per_texel_max", most}};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<Texel> texels = texelSet();
  parallelFor(texels.size(), [&](size_t k) {
    texels[k].exact =
        lut::quadrature(lut::texelCentre(texels[k].i, texels[k].size), lut::texelCentre(texels[k].j, texels[k].size));
  });
  std::vector<std::pair<std::string, lut::QuadratureRule>> rules;
  if (argc > 1) {
    lut::QuadratureRule rule;
    std::string name;
    for (int a = 1; a < argc; ++a) {
      const std::string arg = argv[a];
      const size_t eq = arg.find('=');
      if (eq == std::string::npos || !setField(rule, arg.substr(0, eq), std::atof(arg.c_str() + eq + 1))) {
        std::fprintf(stderr, "usage: mb_bench_lut_rule [field=value...] (fields of lut::QuadratureRule)\n");
        return 2;
      }
      name += (name.empty() ? "" : " ") + arg;
    }
    rules.push_back({name, rule});
  } else {
    rules.push_back({"shipped", {}});
    // Each count one step cheaper (a width one step wider): the criterion must reject every one.
    for (auto [key, value] : std::vector<std::pair<std::string, double>>{{"ggxFullOuter", 10},
                                                                         {"ggxFullInner", 5},
                                                                         {"ggxPartialOuter", 12},
                                                                         {"ggxPartialInner", 7},
                                                                         {"clothOuter", 16},
                                                                         {"clothInner", 3},
                                                                         {"ggxPanelWidth", 5},
                                                                         {"clothPanelWidth", 3.5}}) {
      lut::QuadratureRule r;
      setField(r, key, value);
      char name[64];
      std::snprintf(name, sizeof name, "%s=%g", key.c_str(), value);
      rules.push_back({name, r});
    }
  }
  for (const auto& [name, rule] : rules) std::cout << measure(name, rule, texels).dump() << "\n";
  return 0;
}
