#include "bench_engine/static_cost.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "bench_engine/op_weights.hpp"

#define SPV_ENABLE_UTILITY_CODE
#include <spirv/unified1/spirv.hpp>

namespace mb::bench {
namespace {

struct Instruction {
  uint32_t opcode = 0;
  std::vector<uint32_t> words;  // operands after the opcode word
};

struct Block {
  uint32_t label = 0;
  std::vector<Instruction> body;  // everything but the merge and the terminator
  uint32_t selectionMerge = 0, loopMerge = 0, loopContinue = 0;
  Instruction terminator;
};

struct Function {
  std::unordered_map<uint32_t, Block> blocks;
  uint32_t entry = 0;
};

// The parts of a module the walk needs: types (for component counts), integer constants
// (for trip counts), each result's type and defining instruction, and the functions.
struct Module {
  std::unordered_map<uint32_t, uint32_t> components;  // type id -> components (1 for scalars)
  std::unordered_map<uint32_t, uint32_t> resultType;  // result id -> type id
  std::unordered_map<uint32_t, int64_t> intConstant;
  std::unordered_map<uint32_t, const Instruction*> definition;
  std::unordered_map<uint32_t, Function> functions;
  uint32_t glslStd450 = 0, entryPoint = 0;

  uint32_t componentsOf(uint32_t id) const {
    auto t = resultType.find(id);
    if (t == resultType.end()) return 1;
    auto c = components.find(t->second);
    return c == components.end() ? 1 : c->second;
  }
};

std::string literalString(const std::vector<uint32_t>& w, size_t from) {
  std::string s;
  for (size_t i = from; i < w.size(); ++i)
    for (int b = 0; b < 4; ++b) {
      char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
      if (c == 0) return s;
      s += c;
    }
  return s;
}

Module parse(const std::vector<uint32_t>& spirv) {
  if (spirv.size() < 5 || spirv[0] != spv::MagicNumber) throw std::runtime_error("static cost: not a SPIR-V module");
  Module m;
  Function* fn = nullptr;
  Block* block = nullptr;
  uint32_t fnId = 0;
  for (size_t at = 5; at < spirv.size();) {
    const uint32_t count = spirv[at] >> 16, opcode = spirv[at] & 0xffff;
    if (count == 0 || at + count > spirv.size()) throw std::runtime_error("static cost: truncated SPIR-V");
    Instruction ins{opcode, std::vector<uint32_t>(spirv.begin() + long(at) + 1, spirv.begin() + long(at + count))};
    at += count;
    const auto op = static_cast<spv::Op>(opcode);
    const auto& w = ins.words;
    switch (op) {
      case spv::OpExtInstImport:
        if (literalString(w, 1) == "GLSL.std.450") m.glslStd450 = w[0];
        continue;
      case spv::OpEntryPoint:
        if (!m.entryPoint) m.entryPoint = w[1];
        continue;
      case spv::OpTypeVector:
      case spv::OpTypeMatrix:
        m.components[w[0]] = w[2] * (m.components.count(w[1]) ? m.components[w[1]] : 1);
        continue;
      case spv::OpTypeFloat:
      case spv::OpTypeInt:
      case spv::OpTypeBool:
        m.components[w[0]] = 1;
        continue;
      case spv::OpConstant:
        m.resultType[w[1]] = w[0];
        if (w.size() >= 3) m.intConstant[w[1]] = static_cast<int32_t>(w[2]);  // only integers are ever read back
        continue;
      case spv::OpFunction:
        fnId = w[1];
        fn = &m.functions[fnId];
        continue;
      case spv::OpFunctionEnd:
        fn = nullptr, block = nullptr;
        continue;
      case spv::OpLabel:
        if (!fn) throw std::runtime_error("static cost: label outside a function");
        block = &fn->blocks[w[0]];
        block->label = w[0];
        if (!fn->entry) fn->entry = w[0];
        continue;
      default:
        break;
    }
    if (!block) continue;
    switch (op) {
      case spv::OpSelectionMerge:
        block->selectionMerge = w[0];
        break;
      case spv::OpLoopMerge:
        block->loopMerge = w[0], block->loopContinue = w[1];
        break;
      case spv::OpBranch:
      case spv::OpBranchConditional:
      case spv::OpSwitch:
      case spv::OpReturn:
      case spv::OpReturnValue:
      case spv::OpKill:
      case spv::OpUnreachable:
      case spv::OpTerminateInvocation:
        block->terminator = ins;
        block = nullptr;
        break;
      default:
        block->body.push_back(std::move(ins));
    }
  }
  // Result types and definitions, now that the blocks no longer move.
  for (auto& [id, f] : m.functions)
    for (auto& [label, b] : f.blocks)
      for (const Instruction& ins : b.body) {
        bool hasResult = false, hasType = false;
        spv::HasResultAndType(static_cast<spv::Op>(ins.opcode), &hasResult, &hasType);
        if (hasResult && hasType && ins.words.size() >= 2) {
          m.resultType[ins.words[1]] = ins.words[0];
          m.definition[ins.words[1]] = &ins;
        }
      }
  if (!m.entryPoint || !m.functions.count(m.entryPoint)) throw std::runtime_error("static cost: no entry point");
  return m;
}

constexpr double kNone = -std::numeric_limits<double>::infinity();

// The costliest path from a block to each block where the walk stops, and to a return.
struct Ends {
  std::map<uint32_t, double> at;
  double exit = kNone;
  void add(const Ends& o, double offset) {
    for (auto [label, c] : o.at) {
      auto [it, fresh] = at.emplace(label, c + offset);
      if (!fresh) it->second = std::max(it->second, c + offset);
    }
    if (o.exit != kNone) exit = std::max(exit, o.exit + offset);
  }
};

class Walker {
 public:
  explicit Walker(const Module& m) : m_(m) {}

  double functionCost(uint32_t id) {
    if (auto it = memo_.find(id); it != memo_.end()) return it->second;
    if (!active_.insert(id).second) throw std::runtime_error("static cost: recursive call");
    const Function& f = m_.functions.at(id);
    if (id == m_.entryPoint) entry_ = &f;
    Ends e = walk(f, f.entry, {}, 0);
    active_.erase(id);
    double c = std::max(0.0, e.exit);
    for (auto [label, v] : e.at) c = std::max(c, v);
    return memo_[id] = c;
  }
  StaticCost result;

 private:
  double weight(const Instruction& ins) {
    const auto& w = ins.words;
    if (ins.opcode == spv::OpFunctionCall) return functionCost(w[2]);
    if (ins.opcode == spv::OpExtInst) {
      if (w.size() < 4 || w[2] != m_.glslStd450) return 0;
      bool perComponent = true;
      const uint32_t operand = w.size() > 4 ? m_.componentsOf(w[4]) : 1;
      double x = glslStd450Weight(w[3], operand, perComponent);
      return perComponent ? x * m_.componentsOf(w[1]) : x;
    }
    bool hasResult = false, hasType = false;
    spv::HasResultAndType(static_cast<spv::Op>(ins.opcode), &hasResult, &hasType);
    const uint32_t operand = w.size() > 2 ? m_.componentsOf(w[2]) : 1;
    double x = coreOpWeight(ins.opcode, operand);
    if (x == 0) return 0;
    const bool scalarResult = ins.opcode == spv::OpDot || ins.opcode == spv::OpAny || ins.opcode == spv::OpAll;
    return scalarResult || !hasType ? x : x * m_.componentsOf(w[1]);
  }

  double blockCost(const Block& b) {
    double c = 0;
    for (const Instruction& ins : b.body) c += weight(ins);
    return c;
  }

  static std::vector<uint32_t> successors(const Block& b) {
    const auto& w = b.terminator.words;
    switch (static_cast<spv::Op>(b.terminator.opcode)) {
      case spv::OpBranch:
        return {w[0]};
      case spv::OpBranchConditional:
        return {w[1], w[2]};
      case spv::OpSwitch: {
        std::vector<uint32_t> s{w[1]};
        for (size_t i = 3; i < w.size(); i += 2) s.push_back(w[i]);  // 32-bit selectors
        return s;
      }
      default:
        return {};
    }
  }

  Ends walk(const Function& f, uint32_t label, std::set<uint32_t> stops, int depth) {
    if (depth > 4096) throw std::runtime_error("static cost: control flow too deep");
    Ends out;
    if (stops.count(label)) {
      out.at[label] = 0;
      return out;
    }
    const Block& b = f.blocks.at(label);
    const double own = blockCost(b);
    if (b.loopMerge) {
      ++result.loops;
      std::set<uint32_t> inner = stops;
      inner.insert({b.loopMerge, label});
      Ends body;
      ++loopDepth_;
      for (uint32_t s : successors(b)) body.add(walk(f, s, inner, depth + 1), own);
      --loopDepth_;
      double iteration = own;
      for (uint32_t end : {label, b.loopMerge})
        if (auto it = body.at.find(end); it != body.at.end()) iteration = std::max(iteration, it->second);
      counterOps_ = 0;
      const double trips = tripCount(f, b);
      if (&f == entry_ && loopDepth_ == 0 && !result.outerLoopFound) {
        result.outerLoopFound = true;
        result.outerLoopIteration = iteration - counterOps_;
      }
      const double loop = trips * iteration;
      // Leaving the loop other than through its merge (a return, an outer break): after
      // the loop's cost, as an upper bound.
      for (auto [end, c] : body.at)
        if (end != label && end != b.loopMerge) out.at[end] = std::max(out.at.count(end) ? out.at[end] : kNone, loop);
      if (body.exit != kNone) out.exit = loop;
      out.add(walk(f, b.loopMerge, stops, depth + 1), loop);
      return out;
    }
    const std::vector<uint32_t> next = successors(b);
    if (next.empty()) {
      out.exit = own;
      return out;
    }
    if (b.selectionMerge) {
      std::set<uint32_t> inner = stops;
      inner.insert(b.selectionMerge);
      Ends arms;
      for (uint32_t s : next) arms.add(walk(f, s, inner, depth + 1), own);
      auto merged = arms.at.find(b.selectionMerge);
      if (merged != arms.at.end()) {
        const double toMerge = merged->second;
        arms.at.erase(merged);
        out.add(walk(f, b.selectionMerge, stops, depth + 1), toMerge);
      }
      out.add(arms, 0);
      return out;
    }
    for (uint32_t s : next) out.add(walk(f, s, stops, depth + 1), own);
    return out;
  }

  // Trip count of a loop in the form glslang emits for `for (i = c0; i OP c1; i += c2)`:
  // an OpPhi of the header from a constant and from (phi + constant), the exit test a
  // compare of the phi (tested before the body) or of its increment (after the body,
  // once spirv-opt has rotated the loop) against a constant. Anything else: 1, counted.
  double tripCount(const Function& f, const Block& header) {
    auto unknown = [&] {
      ++result.loopsWithUnknownTripCount;
      return 1.0;
    };
    auto constant = [&](uint32_t id, int64_t& v) {
      auto it = m_.intConstant.find(id);
      return it != m_.intConstant.end() && (v = it->second, true);
    };
    // The exit test: the first conditional branch to the merge on the header's straight path.
    const Block* b = &header;
    const Instruction* test = nullptr;
    for (int step = 0; step < 4 && b; ++step) {
      if (b->terminator.opcode == spv::OpBranchConditional) {
        const auto& w = b->terminator.words;
        if (w[1] == header.loopMerge || w[2] == header.loopMerge) test = &b->terminator;
        break;
      }
      if (b->terminator.opcode != spv::OpBranch) break;
      auto it = f.blocks.find(b->terminator.words[0]);
      b = it == f.blocks.end() || it->first == header.label ? nullptr : &it->second;
    }
    if (!test) return unknown();
    auto cmpIt = m_.definition.find(test->words[0]);
    if (cmpIt == m_.definition.end()) return unknown();
    const Instruction& cmp = *cmpIt->second;
    if (cmp.words.size() < 4) return unknown();
    const bool continueWhenTrue = test->words[1] != header.loopMerge;
    for (const Instruction& phi : header.body) {
      if (phi.opcode != spv::OpPhi || phi.words.size() != 6) continue;
      const uint32_t id = phi.words[1];
      int64_t init = 0, step = 0, bound = 0;
      uint32_t nextId = 0;
      for (int k : {2, 4}) {
        int64_t v;
        if (constant(phi.words[size_t(k)], v))
          init = v;
        else
          nextId = phi.words[size_t(k)];
      }
      auto nextIt = m_.definition.find(nextId);
      if (!nextId || nextIt == m_.definition.end()) continue;
      const Instruction& inc = *nextIt->second;
      if ((inc.opcode != spv::OpIAdd && inc.opcode != spv::OpISub) || inc.words.size() < 4) continue;
      const uint32_t other = inc.words[2] == id ? inc.words[3] : inc.words[3] == id ? inc.words[2] : 0;
      if (!other || !constant(other, step)) continue;
      if (inc.opcode == spv::OpISub) step = -step;
      // Which operand is the counter (the phi, or its increment), which the bound.
      const uint32_t a = cmp.words[2], c = cmp.words[3];
      bool counterFirst;
      if ((a == id || a == nextId) && constant(c, bound))
        counterFirst = true;
      else if ((c == id || c == nextId) && constant(a, bound))
        counterFirst = false;
      else
        continue;
      const bool testsIncrement = (counterFirst ? a : c) == nextId;
      auto holds = [&](int64_t x) {
        int64_t l = counterFirst ? x : bound, r = counterFirst ? bound : x;
        switch (static_cast<spv::Op>(cmp.opcode)) {
          case spv::OpSLessThan:
          case spv::OpULessThan:
            return l < r;
          case spv::OpSLessThanEqual:
          case spv::OpULessThanEqual:
            return l <= r;
          case spv::OpSGreaterThan:
          case spv::OpUGreaterThan:
            return l > r;
          case spv::OpSGreaterThanEqual:
          case spv::OpUGreaterThanEqual:
            return l >= r;
          case spv::OpINotEqual:
            return l != r;
          case spv::OpIEqual:
            return l == r;
          default:
            return false;
        }
      };
      // Count the iterations by running the counter (loops here are short: cap at 2^24).
      int64_t x = init, trips = testsIncrement ? 1 : 0;
      if (testsIncrement) x += step;
      while (trips < (int64_t{1} << 24) && holds(x) == continueWhenTrue) {
        ++trips;
        x += step;
      }
      if (trips >= (int64_t{1} << 24) || trips == 0) return unknown();
      counterOps_ = weight(inc) + weight(cmp);
      return double(trips);
    }
    return unknown();
  }

  const Module& m_;
  std::unordered_map<uint32_t, double> memo_;
  std::set<uint32_t> active_;
  const Function* entry_ = nullptr;
  int loopDepth_ = 0;
  double counterOps_ = 0;  // the weight of the last counted loop's counter increment and exit test
};

}  // namespace

StaticCost staticCost(const std::vector<uint32_t>& spirv) {
  Module m = parse(spirv);
  Walker w(m);
  double c = w.functionCost(m.entryPoint);
  StaticCost s = w.result;
  s.fmaSlots = c;
  return s;
}

double staticCostPerEvaluation(const std::vector<uint32_t>& timed) {
  StaticCost s = staticCost(timed);
  if (!s.outerLoopFound) throw std::runtime_error("static cost: the bench kernel has no loop");
  return s.outerLoopIteration;
}

}  // namespace mb::bench
