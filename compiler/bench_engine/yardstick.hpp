// What bench measures error against (DESIGN.md "compare its reference to check the GPU code,
// and its ground truth to measure the approximation"): a brick's registered ground truth, the
// exact quantity it stands in for; where it has none (an exact brick, or one whose slot has
// no exact quantity), its own reference, which then measures only the fp32 error.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "emit/emitter.hpp"
#include "load/material_desc.hpp"
#include "validate/probe_ltc_table.hpp"

namespace mb::bench {

struct Yardstick {
  std::string kind;  // "ground_truth" or "reference"
  // Bricks replaced by their ground truth (a permutation's composition); empty for a brick.
  std::vector<std::string> groundTruthBricks;
  std::function<void(const double* in, double* out)> eval;
};

Yardstick brickYardstick(const Brick& brick);

// The material's model reference with every bound brick that has a ground truth replaced
// by it: the exact material the permutation approximates, as far as ground truths exist.
// `layout` is the permutation probe's (n, v, l, then the non-constant parameters).
// Throws E-BENCH-SURFACE, at the surface code, for every material with user surface code.
// `ltcTable`: the probe's (ProbeProgram::ltcTable), for rectangle and disk lights.
Yardstick materialYardstick(const MaterialDesc& material, const ProbeLayout& layout,
                            std::shared_ptr<const ProbeLtcTable> ltcTable = nullptr);
// The same check for all materials at once, before any measuring.
void refuseUnmeasurable(const std::vector<MaterialDesc>& materials);

}  // namespace mb::bench
