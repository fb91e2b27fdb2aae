#include "compile/fp16_emulation.hpp"

#include <spirv/unified1/GLSL.std.450.h>
#include <spirv-tools/libspirv.h>

#include <cstring>
#include <map>
#include <set>
#include <spirv/unified1/spirv.hpp11>

#include "compile/glsl_compiler.hpp"
#include "core/diagnostics.hpp"

namespace mb {
namespace {

using spv::Op;

// Constants of the emulation (Vulkan spec, "Precision and Operation of SPIR-V
// Instructions", half-precision column; IEEE 754 binary16).
constexpr float kHalfMinNormal = 0x1p-14f;  // smaller magnitudes are denormal
constexpr float kHalfUlpScale = 0x1p-10f;   // ulp of a half in [2^e, 2^(e+1)) is 2^(e-10)
constexpr float kUlpCap = 0x1p15f;          // binade of the largest finite half
// A perturbation of n ULP (or absolute e) lands on a value that OpQuantizeToF16 then rounds
// to the nearest half, up to half an ulp further: moving by n - 1/2 ULP (e - 2^-11, for
// results of magnitude < 2, whose ulp is <= 2^-10: sin, cos, and log, log2 on [0.5, 2])
// keeps the rounded result inside the bound.
constexpr float kRoundingSlack = 0.5f;
constexpr float kAbsSinCosLog = 0x1p-7f - 0x1p-11f;  // sin, cos; log, log2 inside [0.5, 2]
constexpr float kUlpInverseSqrt = 2.0f - kRoundingSlack;
constexpr float kUlpLog = 3.0f - kRoundingSlack;
constexpr float kUlpAtan = 5.0f - kRoundingSlack;

uint32_t floatBits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// IEEE binary16 bits -> binary32 bits (exact: every half is a float).
uint32_t halfToFloatBits(uint16_t h) {
  const uint32_t sign = static_cast<uint32_t>(h & 0x8000u) << 16;
  const uint32_t exp = (h >> 10) & 0x1fu;
  const uint32_t man = h & 0x3ffu;
  if (exp == 0x1f) return sign | 0x7f800000u | (man << 13);
  if (exp != 0) return sign | ((exp + 112u) << 23) | (man << 13);
  if (man == 0) return sign;
  float f = static_cast<float>(man) * 0x1p-24f;  // subnormal: man * 2^-24, exact in float
  return sign | floatBits(f);
}

struct Inst {
  Op op = Op::OpNop;
  uint32_t typeId = 0;  // after remapping
  uint32_t resultId = 0;
  uint32_t originalType = 0;  // the result type before retyping (half or not)
  std::vector<uint32_t> words;
  std::vector<uint16_t> idOffsets;  // words holding <id> operands other than the result
  uint32_t operand(size_t k) const { return words[k]; }
};

bool isTypeDeclaration(Op op) {
  switch (op) {
    case Op::OpTypeVoid:
    case Op::OpTypeBool:
    case Op::OpTypeInt:
    case Op::OpTypeFloat:
    case Op::OpTypeVector:
    case Op::OpTypeMatrix:
    case Op::OpTypeImage:
    case Op::OpTypeSampler:
    case Op::OpTypeSampledImage:
    case Op::OpTypeArray:
    case Op::OpTypeRuntimeArray:
    case Op::OpTypeStruct:
    case Op::OpTypePointer:
    case Op::OpTypeFunction:
      return true;
    default:
      return false;
  }
}

bool isGlobalDeclaration(Op op) {
  switch (op) {
    case Op::OpConstant:
    case Op::OpConstantTrue:
    case Op::OpConstantFalse:
    case Op::OpConstantComposite:
    case Op::OpConstantNull:
    case Op::OpSpecConstant:
    case Op::OpSpecConstantTrue:
    case Op::OpSpecConstantFalse:
    case Op::OpSpecConstantComposite:
    case Op::OpSpecConstantOp:
    case Op::OpVariable:
    case Op::OpUndef:
      return true;
    default:
      return isTypeDeclaration(op);
  }
}

// What an fp32 float type is, once the half types are retyped.
struct FloatShape {
  uint32_t components = 1;  // of the scalar or vector, or of one column
  uint32_t columns = 0;     // 0: scalar or vector
  uint32_t columnType = 0;  // the column's vector type (matrices)
};

class Emulation {
 public:
  Emulation(const std::vector<uint32_t>& spirv, std::string displayName, Denormals denormals, Fp16EmulationStats& stats)
      : displayName_(std::move(displayName)), denormals_(denormals), stats_(stats) {
    parse(spirv);
  }

  std::vector<uint32_t> run() {
    retypeGlobals();
    remapSection(preamble_, true);
    for (auto& in : functions_) remap(in);
    glslSet_ = findGlslSet();
    std::vector<Inst> body;
    body.reserve(functions_.size() * 3);
    for (const Inst& in : functions_) {
      out_ = &body;
      if (!rewrite(in)) body.push_back(in);
    }
    functions_ = std::move(body);
    std::vector<uint32_t> out = assemble();
    const std::string invalid = spirvValidationErrors(out, SPV_ENV_VULKAN_1_1);
    if (!invalid.empty()) fail("spirv-val rejected the emulated module: " + invalid);
    return out;
  }

 private:
  // ---- parsing and writing -------------------------------------------------------------

  static spv_result_t onInstruction(void* user, const spv_parsed_instruction_t* p) {
    auto* self = static_cast<Emulation*>(user);
    Inst in;
    in.op = static_cast<Op>(p->opcode);
    in.typeId = p->type_id;
    in.originalType = p->type_id;
    in.resultId = p->result_id;
    in.words.assign(p->words, p->words + p->num_words);
    for (uint16_t k = 0; k < p->num_operands; ++k) {
      const spv_parsed_operand_t& o = p->operands[k];
      switch (o.type) {
        case SPV_OPERAND_TYPE_ID:
        case SPV_OPERAND_TYPE_TYPE_ID:
        case SPV_OPERAND_TYPE_SCOPE_ID:
        case SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID:
          in.idOffsets.push_back(o.offset);
          break;
        default:
          break;
      }
    }
    self->all_.push_back(std::move(in));
    return SPV_SUCCESS;
  }

  void parse(const std::vector<uint32_t>& spirv) {
    if (spirv.size() < 5) fail("not a SPIR-V module");
    header_.assign(spirv.begin(), spirv.begin() + 5);
    bound_ = spirv[3];
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_1);
    spv_diagnostic diagnostic = nullptr;
    spv_result_t r =
        spvBinaryParse(context, this, spirv.data(), spirv.size(), nullptr, &Emulation::onInstruction, &diagnostic);
    std::string message = diagnostic && diagnostic->error ? diagnostic->error : "";
    spvDiagnosticDestroy(diagnostic);
    spvContextDestroy(context);
    if (r != SPV_SUCCESS) fail("cannot parse the module: " + message);
    // Sections: everything before the first type/constant/global variable, the globals up
    // to the first function, and the functions.
    int section = 0;
    for (auto& in : all_) {
      if (section == 0 && isGlobalDeclaration(in.op)) section = 1;
      if (section == 1 && in.op == Op::OpFunction) section = 2;
      (section == 0 ? preamble_ : section == 1 ? globals_ : functions_).push_back(std::move(in));
    }
    all_.clear();
    for (const auto& in : preamble_)
      if (in.op == Op::OpDecorate || in.op == Op::OpMemberDecorate) decorated_.insert(in.words[1]);
  }

  std::vector<uint32_t> assemble() {
    std::vector<uint32_t> out = header_;
    out[3] = bound_;
    auto put = [&](const std::vector<Inst>& section) {
      for (const auto& in : section) out.insert(out.end(), in.words.begin(), in.words.end());
    };
    put(preamble_);
    put(globals_);
    put(newGlobals_);
    put(functions_);
    return out;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw DiagnosticError({{Severity::Error,
                            "E-FP16-EMULATION",
                            {displayName_, 0, 0},
                            "fp16 emulation: " + what,
                            "run with --fp16 driver to use the device's own half arithmetic"}});
  }

  // ---- retyping ------------------------------------------------------------------------

  uint32_t mapped(uint32_t id) const {
    auto it = remap_.find(id);
    return it == remap_.end() ? id : it->second;
  }

  void remap(Inst& in) {
    for (uint16_t off : in.idOffsets) in.words[off] = mapped(in.words[off]);
    if (in.typeId) in.typeId = mapped(in.typeId);
  }

  // Names of dropped (deduplicated) types go; everything else is remapped.
  void remapSection(std::vector<Inst>& section, bool dropNamesOfRemoved) {
    std::vector<Inst> kept;
    for (auto& in : section) {
      if (dropNamesOfRemoved && (in.op == Op::OpName || in.op == Op::OpMemberName) && remap_.count(in.words[1]))
        continue;
      remap(in);
      if (in.op == Op::OpCapability && in.words[1] == static_cast<uint32_t>(spv::Capability::Float16)) continue;
      kept.push_back(std::move(in));
    }
    section = std::move(kept);
  }

  static std::vector<uint32_t> signature(const Inst& in) {
    std::vector<uint32_t> sig = in.words;
    sig.erase(sig.begin() + 1);  // the result id
    return sig;
  }

  void retypeGlobals() {
    std::vector<Inst> kept;
    for (auto& in : globals_) {
      const bool wasHalf = declaresHalf(in);
      if (in.op == Op::OpTypeFloat && in.words[2] == 16) in.words[2] = 32;
      remap(in);
      if ((in.op == Op::OpConstant || in.op == Op::OpSpecConstant) && halfTypes_.count(in.originalType))
        in.words[3] = halfToFloatBits(static_cast<uint16_t>(in.words[3] & 0xffffu));
      if (wasHalf) halfTypes_.insert(in.resultId);
      if (isTypeDeclaration(in.op) && in.op != Op::OpTypeStruct && !decorated_.count(in.resultId)) {
        auto sig = signature(in);
        auto it = types_.find(sig);
        if (it != types_.end()) {
          remap_[in.resultId] = it->second;
          continue;
        }
        types_[sig] = in.resultId;
      }
      noteShape(in);
      if (in.resultId && in.typeId) typeOf_[in.resultId] = in.typeId;
      kept.push_back(std::move(in));
    }
    globals_ = std::move(kept);
    for (const auto& in : functions_)
      if (in.resultId && in.typeId) typeOf_[in.resultId] = mapped(in.typeId);
  }

  bool declaresHalf(const Inst& in) const {
    switch (in.op) {
      case Op::OpTypeFloat:
        return in.words[2] == 16;
      case Op::OpTypeVector:
      case Op::OpTypeMatrix:
        return halfTypes_.count(in.words[2]) != 0;
      default:
        return false;
    }
  }

  void noteShape(const Inst& in) {
    if (in.op == Op::OpTypeFloat && in.words[2] == 32) shapes_[in.resultId] = {1, 0, 0};
    if (in.op == Op::OpTypeVector && shapes_.count(in.words[2])) shapes_[in.resultId] = {in.words[3], 0, 0};
    if (in.op == Op::OpTypeMatrix && shapes_.count(in.words[2]))
      shapes_[in.resultId] = {shapes_[in.words[2]].components, in.words[3], in.words[2]};
  }

  // ---- building ------------------------------------------------------------------------

  uint32_t newId() { return bound_++; }

  uint32_t declareType(std::vector<uint32_t> sig) {
    auto it = types_.find(sig);
    if (it != types_.end()) return it->second;
    Inst in;
    in.op = static_cast<Op>(sig[0] & 0xffffu);
    in.resultId = newId();
    in.words = sig;
    in.words.insert(in.words.begin() + 1, in.resultId);
    types_[sig] = in.resultId;
    noteShape(in);
    newGlobals_.push_back(in);
    return in.resultId;
  }
  static uint32_t opWord(Op op, size_t words) {
    return (static_cast<uint32_t>(words) << 16) | static_cast<uint32_t>(op);
  }
  uint32_t scalarType(Op op, std::initializer_list<uint32_t> operands) {
    std::vector<uint32_t> sig{opWord(op, operands.size() + 2)};
    sig.insert(sig.end(), operands);
    return declareType(sig);
  }
  uint32_t vectorOf(uint32_t scalar, uint32_t n) {
    return n == 1 ? scalar : declareType({opWord(Op::OpTypeVector, 4), scalar, n});
  }
  uint32_t floatT(uint32_t n) { return vectorOf(scalarType(Op::OpTypeFloat, {32}), n); }
  uint32_t uintT(uint32_t n) { return vectorOf(scalarType(Op::OpTypeInt, {32, 0}), n); }
  uint32_t boolT(uint32_t n) { return vectorOf(scalarType(Op::OpTypeBool, {}), n); }

  uint32_t constant(uint32_t scalarTypeId, uint32_t bits, uint32_t n) {
    auto key = std::make_tuple(scalarTypeId, bits, n);
    auto it = constants_.find(key);
    if (it != constants_.end()) return it->second;
    Inst in;
    in.resultId = newId();
    if (n == 1) {
      in.op = Op::OpConstant;
      in.words = {opWord(Op::OpConstant, 4), scalarTypeId, in.resultId, bits};
    } else {
      uint32_t c = constant(scalarTypeId, bits, 1);
      in.op = Op::OpConstantComposite;
      in.words = {opWord(Op::OpConstantComposite, 3 + n), vectorOf(scalarTypeId, n), in.resultId};
      for (uint32_t k = 0; k < n; ++k) in.words.push_back(c);
    }
    newGlobals_.push_back(in);
    constants_[key] = in.resultId;
    return in.resultId;
  }
  uint32_t constF(uint32_t type, float v) { return constant(floatT(1), floatBits(v), shape(type).components); }
  uint32_t constU(uint32_t n, uint32_t v) { return constant(uintT(1), v, n); }

  const FloatShape& shape(uint32_t type) const {
    auto it = shapes_.find(type);
    if (it == shapes_.end()) fail("a half value of an unexpected type (%" + std::to_string(type) + ")");
    return it->second;
  }
  uint32_t typeOf(uint32_t value) const {
    auto it = typeOf_.find(value);
    if (it == typeOf_.end()) fail("no type known for %" + std::to_string(value));
    return it->second;
  }

  uint32_t emit(Op op, uint32_t type, std::initializer_list<uint32_t> operands) {
    Inst in;
    in.op = op;
    in.typeId = type;
    in.resultId = newId();
    in.words = {opWord(op, operands.size() + 3), type, in.resultId};
    in.words.insert(in.words.end(), operands);
    const uint32_t id = in.resultId;
    out_->push_back(std::move(in));
    typeOf_[id] = type;
    return id;
  }
  uint32_t ext(GLSLstd450 f, uint32_t type, std::initializer_list<uint32_t> args) {
    Inst in;
    in.op = Op::OpExtInst;
    in.typeId = type;
    in.resultId = newId();
    in.words = {opWord(Op::OpExtInst, args.size() + 5), type, in.resultId, glslSet_, static_cast<uint32_t>(f)};
    in.words.insert(in.words.end(), args);
    out_->push_back(std::move(in));
    typeOf_[in.resultId] = type;
    return in.resultId;
  }
  void copyTo(uint32_t resultId, uint32_t type, uint32_t value) {
    Inst in;
    in.op = Op::OpCopyObject;
    in.typeId = type;
    in.resultId = resultId;
    in.words = {opWord(Op::OpCopyObject, 4), type, resultId, value};
    out_->push_back(std::move(in));
  }

  uint32_t findGlslSet() {
    for (const auto& in : preamble_) {
      if (in.op != Op::OpExtInstImport) continue;
      const char* name = reinterpret_cast<const char*>(&in.words[2]);
      if (std::strncmp(name, "GLSL.std.450", (in.words.size() - 2) * 4) == 0) return in.resultId;
    }
    // None yet: import it after the capabilities and extensions.
    Inst in;
    in.op = Op::OpExtInstImport;
    in.resultId = newId();
    const char name[16] = "GLSL.std.450";  // 13 bytes with the NUL, padded to 4 words
    in.words = {opWord(Op::OpExtInstImport, 6), in.resultId, 0, 0, 0, 0};
    std::memcpy(&in.words[2], name, sizeof name);
    auto pos = preamble_.begin();
    while (pos != preamble_.end() && (pos->op == Op::OpCapability || pos->op == Op::OpExtension)) ++pos;
    preamble_.insert(pos, in);
    return in.resultId;
  }

  // ---- the emulated arithmetic -----------------------------------------------------------
  // Every helper takes fp32 values holding halves and returns the id of an fp32 value
  // holding the emulated half result.

  // Round to half: OpQuantizeToF16 (correctly rounded, overflow to +-Inf). Its result for
  // |x| < 2^-14 "may be either +0 or -0" or a denormal, so that range is handled explicitly:
  // Flush: a zero of x's sign, x * step(2^-14, |x|) (0 * finite keeps the sign);
  // Keep: x rounded to the denormal grid, roundEven(x * 2^24) * 2^-24 (both scalings exact).
  uint32_t round(uint32_t t, uint32_t x) {
    const FloatShape& s = shape(t);
    if (s.columns)
      return perColumn(
          t, [&](uint32_t ct, uint32_t col) { return round(ct, col); }, x);
    ++stats_.rounded;
    uint32_t q = emit(Op::OpQuantizeToF16, t, {x});
    if (denormals_ == Denormals::Flush) {
      uint32_t keep = ext(GLSLstd450Step, t, {constF(t, kHalfMinNormal), ext(GLSLstd450FAbs, t, {q})});
      return emit(Op::OpFMul, t, {q, keep});
    }
    const uint32_t n = s.components;
    uint32_t small = emit(Op::OpFOrdLessThan, boolT(n), {ext(GLSLstd450FAbs, t, {x}), constF(t, kHalfMinNormal)});
    uint32_t grid = ext(GLSLstd450RoundEven, t, {emit(Op::OpFMul, t, {x, constF(t, 0x1p24f)})});
    uint32_t denormal = emit(Op::OpFMul, t, {grid, constF(t, 0x1p-24f)});
    return emit(Op::OpSelect, t, {small, denormal, q});
  }

  template <class F>
  uint32_t perColumn(uint32_t t, F f, uint32_t m) {
    const FloatShape s = shape(t);
    std::vector<uint32_t> cols;
    for (uint32_t c = 0; c < s.columns; ++c)
      cols.push_back(f(s.columnType, emit(Op::OpCompositeExtract, s.columnType, {m, c})));
    return construct(t, cols);
  }
  uint32_t construct(uint32_t t, const std::vector<uint32_t>& parts) {
    Inst in;
    in.op = Op::OpCompositeConstruct;
    in.typeId = t;
    in.resultId = newId();
    in.words = {opWord(Op::OpCompositeConstruct, parts.size() + 3), t, in.resultId};
    in.words.insert(in.words.end(), parts.begin(), parts.end());
    out_->push_back(std::move(in));
    typeOf_[in.resultId] = t;
    return in.resultId;
  }

  uint32_t binary(Op op, uint32_t t, uint32_t a, uint32_t b) { return round(t, emit(op, t, {a, b})); }
  uint32_t mul(uint32_t t, uint32_t a, uint32_t b) { return binary(Op::OpFMul, t, a, b); }
  uint32_t add(uint32_t t, uint32_t a, uint32_t b) { return binary(Op::OpFAdd, t, a, b); }
  uint32_t sub(uint32_t t, uint32_t a, uint32_t b) { return binary(Op::OpFSub, t, a, b); }

  // x / y as x * (1/y), the reciprocal rounded and flushed first.
  uint32_t div(uint32_t t, uint32_t x, uint32_t y) {
    ++stats_.divisions;
    uint32_t rcp = round(t, emit(Op::OpFDiv, t, {constF(t, 1.0f), y}));
    return mul(t, x, rcp);
  }

  uint32_t component(uint32_t v, uint32_t k) {
    return shape(typeOf(v)).components == 1 ? v : emit(Op::OpCompositeExtract, floatT(1), {v, k});
  }

  // Sum of products, rounded after every product and every addition, in index order.
  uint32_t dot(uint32_t a, uint32_t b) {
    const uint32_t n = shape(typeOf(a)).components;
    const uint32_t f = floatT(1);
    uint32_t acc = mul(f, component(a, 0), component(b, 0));
    for (uint32_t k = 1; k < n; ++k) acc = add(f, acc, mul(f, component(a, k), component(b, k)));
    return acc;
  }

  // A splat of scalar s to the vector type t.
  uint32_t splat(uint32_t t, uint32_t s) {
    const uint32_t n = shape(t).components;
    if (n == 1) return s;
    return construct(t, std::vector<uint32_t>(n, s));
  }

  // ---- the perturbation of results with an error bound --------------------------------

  uint32_t bitsOf(uint32_t t, uint32_t x) { return emit(Op::OpBitcast, uintT(shape(t).components), {x}); }

  // +1 or -1 per component, from a hash of the operand bits: the top bit of a Fibonacci
  // (multiplicative) hash, which every bit of the operand reaches through the carries.
  uint32_t signFromBits(uint32_t t, uint32_t bits) {
    const uint32_t n = shape(t).components;
    const uint32_t u = uintT(n);
    uint32_t h = emit(Op::OpIMul, u, {bits, constU(n, 0x9e3779b1u)});
    uint32_t top = emit(Op::OpShiftRightLogical, u, {h, constU(n, 31)});
    uint32_t f = emit(Op::OpConvertUToF, t, {top});
    return emit(Op::OpFAdd, t, {constF(t, 1.0f), emit(Op::OpFMul, t, {f, constF(t, -2.0f)})});
  }

  // ulp of the half binade of |r| (the spacing below it at an exact power of two, as the
  // spec's ulp(x) is the smallest gap around x), capped at the largest finite binade.
  uint32_t ulpOf(uint32_t t, uint32_t r) {
    const uint32_t n = shape(t).components;
    uint32_t below = emit(Op::OpFMul, t, {ext(GLSLstd450FAbs, t, {r}), constF(t, 1.0f - 0x1p-12f)});
    uint32_t exponent = emit(Op::OpBitwiseAnd, uintT(n), {bitsOf(t, below), constU(n, 0x7f800000u)});
    uint32_t binade = ext(GLSLstd450FMin, t, {emit(Op::OpBitcast, t, {exponent}), constF(t, kUlpCap)});
    return emit(Op::OpFMul, t, {binade, constF(t, kHalfUlpScale)});
  }

  // r moved by `delta` (>= 0) in the direction hashed from `bits`, then rounded.
  uint32_t perturb(uint32_t t, uint32_t r, uint32_t delta, uint32_t bits) {
    ++stats_.perturbed;
    uint32_t moved = emit(Op::OpFAdd, t, {r, emit(Op::OpFMul, t, {signFromBits(t, bits), delta})});
    return round(t, moved);
  }
  uint32_t perturbUlps(uint32_t t, uint32_t r, uint32_t ulps, uint32_t bits) {
    return perturb(t, r, emit(Op::OpFMul, t, {ulpOf(t, r), ulps}), bits);
  }

  uint32_t exp(GLSLstd450 f, uint32_t t, uint32_t x) {
    // 1 + 2|x| ULP; capped, so that exp(-Inf) = 0 moves by 0 ULP * 0 rather than Inf * 0.
    uint32_t ulps =
        emit(Op::OpFAdd, t,
             {emit(Op::OpFMul, t, {ext(GLSLstd450FAbs, t, {x}), constF(t, 2.0f)}), constF(t, 1.0f - kRoundingSlack)});
    ulps = ext(GLSLstd450FMin, t, {ulps, constF(t, kUlpCap)});
    return perturbUlps(t, ext(f, t, {x}), ulps, bitsOf(t, x));
  }
  uint32_t log(GLSLstd450 f, uint32_t t, uint32_t x) {
    // 3 ULP outside [0.5, 2]; absolute 2^-7 inside.
    const uint32_t n = shape(t).components;
    uint32_t r = ext(f, t, {x});
    uint32_t inside = emit(Op::OpLogicalAnd, boolT(n),
                           {emit(Op::OpFOrdGreaterThanEqual, boolT(n), {x, constF(t, 0.5f)}),
                            emit(Op::OpFOrdLessThanEqual, boolT(n), {x, constF(t, 2.0f)})});
    uint32_t ulpDelta = emit(Op::OpFMul, t, {ulpOf(t, r), constF(t, kUlpLog)});
    uint32_t delta = emit(Op::OpSelect, t, {inside, constF(t, kAbsSinCosLog), ulpDelta});
    return perturb(t, r, delta, bitsOf(t, x));
  }
  uint32_t inverseSqrt(uint32_t t, uint32_t x) {
    return perturbUlps(t, ext(GLSLstd450InverseSqrt, t, {x}), constF(t, kUlpInverseSqrt), bitsOf(t, x));
  }
  uint32_t sqrt(uint32_t t, uint32_t x) { return div(t, constF(t, 1.0f), inverseSqrt(t, x)); }
  uint32_t sinCos(GLSLstd450 f, uint32_t t, uint32_t x) {
    return perturb(t, ext(f, t, {x}), constF(t, kAbsSinCosLog), bitsOf(t, x));
  }
  uint32_t atan2(uint32_t t, uint32_t y, uint32_t x) {
    const uint32_t n = shape(t).components;
    uint32_t bits = emit(Op::OpBitwiseXor, uintT(n),
                         {bitsOf(t, y), emit(Op::OpShiftLeftLogical, uintT(n), {bitsOf(t, x), constU(n, 16)})});
    uint32_t r = perturbUlps(t, ext(GLSLstd450Atan2, t, {y, x}), constF(t, kUlpAtan), bits);
    // atan2(0, 0) is not mathematically defined, so "the value returned is undefined" (the
    // spec's ULP rule): NaN, as hardware that forms y / x returns.
    const uint32_t b = boolT(n);
    uint32_t undefined =
        emit(Op::OpLogicalAnd, b,
             {emit(Op::OpFOrdEqual, b, {y, constF(t, 0.0f)}), emit(Op::OpFOrdEqual, b, {x, constF(t, 0.0f)})});
    return emit(Op::OpSelect, t, {undefined, constant(floatT(1), 0x7fc00000u, n), r});
  }
  uint32_t oneMinusSquare(uint32_t t, uint32_t x) { return sub(t, constF(t, 1.0f), mul(t, x, x)); }

  // The GLSL.std.450 instruction `f` on operands `a` (fp32 values holding halves).
  uint32_t extended(uint32_t f, uint32_t t, const std::vector<uint32_t>& a) {
    const uint32_t f1 = floatT(1);
    switch (f) {
      // Correctly rounded: computed in fp32 (exact or correctly rounded for half operands,
      // whose precision is well inside fp32's), then rounded to half.
      case GLSLstd450Round:
      case GLSLstd450RoundEven:
      case GLSLstd450Trunc:
      case GLSLstd450FAbs:
      case GLSLstd450FSign:
      case GLSLstd450Floor:
      case GLSLstd450Ceil:
      case GLSLstd450Fract:
      case GLSLstd450FMin:
      case GLSLstd450FMax:
      case GLSLstd450FClamp:
      case GLSLstd450Step:
      case GLSLstd450NMin:
      case GLSLstd450NMax:
      case GLSLstd450NClamp:
      case GLSLstd450Ldexp: {
        Inst in;
        in.op = Op::OpExtInst;
        in.typeId = t;
        in.resultId = newId();
        in.words = {opWord(Op::OpExtInst, a.size() + 5), t, in.resultId, glslSet_, f};
        in.words.insert(in.words.end(), a.begin(), a.end());
        const uint32_t id = in.resultId;
        out_->push_back(std::move(in));
        typeOf_[id] = t;
        return round(t, id);
      }
      case GLSLstd450Radians:
        return mul(t, a[0], constF(t, static_cast<float>(3.14159265358979323846 / 180.0)));
      case GLSLstd450Degrees:
        return mul(t, a[0], constF(t, static_cast<float>(180.0 / 3.14159265358979323846)));
      case GLSLstd450Exp:
      case GLSLstd450Exp2:
        return exp(static_cast<GLSLstd450>(f), t, a[0]);
      case GLSLstd450Log:
      case GLSLstd450Log2:
        return log(static_cast<GLSLstd450>(f), t, a[0]);
      case GLSLstd450InverseSqrt:
        return inverseSqrt(t, a[0]);
      case GLSLstd450Sin:
      case GLSLstd450Cos:
        return sinCos(static_cast<GLSLstd450>(f), t, a[0]);
      case GLSLstd450Atan:
        return atan2(t, a[0], constF(t, 1.0f));
      case GLSLstd450Atan2:
        return atan2(t, a[0], a[1]);
      // Inherited from formulas: expanded, each step rounded.
      case GLSLstd450Sqrt:
        ++stats_.expanded;
        return sqrt(t, a[0]);
      case GLSLstd450Pow:
        ++stats_.expanded;
        return exp(GLSLstd450Exp2, t, mul(t, a[1], log(GLSLstd450Log2, t, a[0])));
      case GLSLstd450Tan:
        ++stats_.expanded;
        return div(t, sinCos(GLSLstd450Sin, t, a[0]), sinCos(GLSLstd450Cos, t, a[0]));
      case GLSLstd450Asin:
        ++stats_.expanded;
        return atan2(t, a[0], sqrt(t, oneMinusSquare(t, a[0])));
      case GLSLstd450Acos:
        ++stats_.expanded;
        return atan2(t, sqrt(t, oneMinusSquare(t, a[0])), a[0]);
      case GLSLstd450Fma:
        ++stats_.expanded;
        return add(t, mul(t, a[0], a[1]), a[2]);
      case GLSLstd450FMix:
        ++stats_.expanded;
        return add(t, mul(t, a[0], sub(t, constF(t, 1.0f), a[2])), mul(t, a[1], a[2]));
      case GLSLstd450SmoothStep: {
        ++stats_.expanded;
        uint32_t x = div(t, sub(t, a[2], a[0]), sub(t, a[1], a[0]));
        x = round(t, ext(GLSLstd450FClamp, t, {x, constF(t, 0.0f), constF(t, 1.0f)}));
        return mul(t, mul(t, x, x), sub(t, constF(t, 3.0f), mul(t, constF(t, 2.0f), x)));
      }
      case GLSLstd450Length:
        ++stats_.expanded;
        return sqrt(f1, dot(a[0], a[0]));
      case GLSLstd450Distance: {
        ++stats_.expanded;
        uint32_t d = sub(typeOf(a[0]), a[0], a[1]);
        return sqrt(f1, dot(d, d));
      }
      case GLSLstd450Normalize: {
        ++stats_.expanded;
        uint32_t s = inverseSqrt(f1, dot(a[0], a[0]));
        return round(t, emit(Op::OpVectorTimesScalar, t, {a[0], s}));
      }
      case GLSLstd450Cross: {
        ++stats_.expanded;
        auto shuffle = [&](uint32_t v, uint32_t i, uint32_t j, uint32_t k) {
          Inst in;
          in.op = Op::OpVectorShuffle;
          in.typeId = t;
          in.resultId = newId();
          in.words = {opWord(Op::OpVectorShuffle, 8), t, in.resultId, v, v, i, j, k};
          const uint32_t id = in.resultId;
          out_->push_back(std::move(in));
          typeOf_[id] = t;
          return id;
        };
        uint32_t p = mul(t, shuffle(a[0], 1, 2, 0), shuffle(a[1], 2, 0, 1));
        uint32_t q = mul(t, shuffle(a[0], 2, 0, 1), shuffle(a[1], 1, 2, 0));
        return sub(t, p, q);
      }
      case GLSLstd450Reflect: {
        ++stats_.expanded;
        uint32_t k = mul(f1, constF(f1, 2.0f), dot(a[1], a[0]));
        return sub(t, a[0], round(t, emit(Op::OpVectorTimesScalar, t, {a[1], k})));
      }
      case GLSLstd450FaceForward: {
        ++stats_.expanded;
        uint32_t d = dot(a[2], a[1]);
        uint32_t front = emit(Op::OpFOrdLessThan, boolT(1), {d, constF(f1, 0.0f)});
        return emit(Op::OpSelect, t, {splatBool(t, front), a[0], emit(Op::OpFNegate, t, {a[0]})});
      }
      default:
        fail("GLSL.std.450 instruction " + std::to_string(f) + " on half values is not emulated");
    }
  }

  uint32_t splatBool(uint32_t t, uint32_t b) {
    const uint32_t n = shape(t).components;
    if (n == 1) return b;
    uint32_t bt = boolT(n);
    Inst in;
    in.op = Op::OpCompositeConstruct;
    in.typeId = bt;
    in.resultId = newId();
    in.words = {opWord(Op::OpCompositeConstruct, n + 3), bt, in.resultId};
    for (uint32_t k = 0; k < n; ++k) in.words.push_back(b);
    const uint32_t id = in.resultId;
    out_->push_back(std::move(in));
    return id;
  }

  // matrix * vector: the columns scaled by the vector's components, summed in order.
  uint32_t matrixTimesVector(uint32_t m, uint32_t v) {
    const FloatShape s = shape(typeOf(m));
    uint32_t ct = s.columnType;
    uint32_t acc = 0;
    for (uint32_t c = 0; c < s.columns; ++c) {
      uint32_t col = emit(Op::OpCompositeExtract, ct, {m, c});
      uint32_t term = round(ct, emit(Op::OpVectorTimesScalar, ct, {col, component(v, c)}));
      acc = c == 0 ? term : add(ct, acc, term);
    }
    return acc;
  }

  // Replaces `in` when it computes a half result; false when it is kept as it is.
  bool rewrite(const Inst& in) {
    if (in.op == Op::OpFConvert) {
      if (halfTypes_.count(in.originalType)) {
        copyTo(in.resultId, in.typeId, round(in.typeId, in.words[3]));  // fp32 -> half
      } else if (isHalfValue(in.words[3])) {
        copyTo(in.resultId, in.typeId, in.words[3]);  // half -> fp32: exact
      } else {
        return false;
      }
      return true;
    }
    if (in.op == Op::OpBitcast && (halfTypes_.count(in.originalType) || isHalfValue(in.words[3])))
      fail("a bitcast of a 16-bit float cannot be emulated in 32 bits");
    if (!halfTypes_.count(in.originalType)) return false;
    const uint32_t t = in.typeId;
    const auto& w = in.words;
    uint32_t r = 0;
    switch (in.op) {
      case Op::OpFAdd:
      case Op::OpFSub:
      case Op::OpFMul:
      case Op::OpVectorTimesScalar:
        r = binary(in.op, t, w[3], w[4]);
        break;
      case Op::OpMatrixTimesScalar:
        r = perColumn(
            t, [&](uint32_t ct, uint32_t col) { return mul(ct, col, splat(ct, w[4])); }, w[3]);
        break;
      case Op::OpFDiv:
        r = div(t, w[3], w[4]);
        break;
      case Op::OpFMod:
      case Op::OpFRem: {
        // Inherited from x - y * floor(x / y) (OpFMod) or x - y * trunc(x / y) (OpFRem).
        ++stats_.expanded;
        uint32_t q = div(t, w[3], w[4]);
        q = ext(in.op == Op::OpFMod ? GLSLstd450Floor : GLSLstd450Trunc, t, {q});
        r = sub(t, w[3], mul(t, w[4], q));
        break;
      }
      case Op::OpDot:
        ++stats_.expanded;
        r = dot(w[3], w[4]);
        break;
      case Op::OpMatrixTimesVector:
        ++stats_.expanded;
        r = matrixTimesVector(w[3], w[4]);
        break;
      case Op::OpVectorTimesMatrix: {
        ++stats_.expanded;
        const FloatShape s = shape(typeOf(w[4]));
        std::vector<uint32_t> parts;
        for (uint32_t c = 0; c < s.columns; ++c)
          parts.push_back(dot(w[3], emit(Op::OpCompositeExtract, s.columnType, {w[4], c})));
        r = shape(t).components == 1 ? parts[0] : construct(t, parts);
        break;
      }
      case Op::OpMatrixTimesMatrix:
        ++stats_.expanded;
        r = perColumn(
            t, [&](uint32_t, uint32_t col) { return matrixTimesVector(w[3], col); }, w[4]);
        break;
      case Op::OpConvertSToF:
      case Op::OpConvertUToF:
        r = round(t, emit(in.op, t, {w[3]}));
        break;
      case Op::OpExtInst: {
        if (w[3] != glslSet_) fail("an extended instruction set other than GLSL.std.450 on half values");
        r = extended(w[4], t, std::vector<uint32_t>(w.begin() + 5, w.end()));
        break;
      }
      case Op::OpFNegate:  // exact
      case Op::OpLoad:
      case Op::OpStore:
      case Op::OpCopyObject:
      case Op::OpCompositeConstruct:
      case Op::OpCompositeExtract:
      case Op::OpCompositeInsert:
      case Op::OpVectorShuffle:
      case Op::OpVectorExtractDynamic:
      case Op::OpVectorInsertDynamic:
      case Op::OpSelect:
      case Op::OpPhi:
      case Op::OpFunctionCall:
      case Op::OpFunctionParameter:
      case Op::OpFunction:
      case Op::OpVariable:
      case Op::OpUndef:
      case Op::OpTranspose:
      case Op::OpAccessChain:
        return false;  // moves half values without arithmetic
      default:
        fail("opcode " + std::to_string(static_cast<uint32_t>(in.op)) + " with a half result is not emulated");
    }
    copyTo(in.resultId, t, r);
    return true;
  }

  bool isHalfValue(uint32_t id) const {
    auto it = originalTypeOf_.find(id);
    return it != originalTypeOf_.end() && halfTypes_.count(it->second);
  }

 public:
  void recordOriginalTypes() {
    for (const auto* section : {&globals_, &functions_})
      for (const auto& in : *section)
        if (in.resultId && in.originalType) originalTypeOf_[in.resultId] = in.originalType;
  }

 private:
  std::string displayName_;
  Denormals denormals_;
  Fp16EmulationStats& stats_;
  std::vector<uint32_t> header_;
  uint32_t bound_ = 0;
  std::vector<Inst> all_, preamble_, globals_, newGlobals_, functions_;
  std::vector<Inst>* out_ = nullptr;
  std::set<uint32_t> decorated_;
  std::set<uint32_t> halfTypes_;  // original ids of half scalar, vector and matrix types
  std::map<uint32_t, uint32_t> remap_;
  std::map<std::vector<uint32_t>, uint32_t> types_;
  std::map<uint32_t, FloatShape> shapes_;
  std::map<uint32_t, uint32_t> typeOf_;          // value -> its (retyped) type
  std::map<uint32_t, uint32_t> originalTypeOf_;  // value -> its type before retyping
  std::map<std::tuple<uint32_t, uint32_t, uint32_t>, uint32_t> constants_;
  uint32_t glslSet_ = 0;
};

}  // namespace

std::vector<uint32_t> emulateWorstCaseFp16(const std::vector<uint32_t>& spirv, const std::string& displayName,
                                           Denormals denormals, Fp16EmulationStats& stats) {
  Emulation e(spirv, displayName, denormals, stats);
  e.recordOriginalTypes();
  return e.run();
}

std::vector<uint32_t> emulateWorstCaseFp16(const std::vector<uint32_t>& spirv, const std::string& displayName,
                                           Denormals denormals) {
  Fp16EmulationStats stats;
  return emulateWorstCaseFp16(spirv, displayName, denormals, stats);
}

}  // namespace mb
