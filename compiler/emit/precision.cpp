#include "emit/precision.hpp"

namespace mb {

const char* precisionName(ShaderPrecision p) { return isHalf(p) ? "fp16" : "fp32"; }

const char* fp16ModeName(Fp16Mode m) { return m == Fp16Mode::Emulated ? "emulated" : "driver"; }

std::optional<Fp16Mode> parseFp16Mode(const std::string& name) {
  if (name == "emulated") return Fp16Mode::Emulated;
  if (name == "driver") return Fp16Mode::Driver;
  return std::nullopt;
}

double minPerceptualRoughness(ShaderPrecision p) {
  return isHalf(p) ? kMinPerceptualRoughnessFp16 : kMinPerceptualRoughnessFp32;
}

double minAlpha(ShaderPrecision p) {
  double r = minPerceptualRoughness(p);
  return r * r;
}

std::string brickForPrecision(const ShaderLibrary& lib, const std::string& brickId, ShaderPrecision p) {
  const Brick* b = lib.findBrick(brickId);
  if (isHalf(p) && b && !b->fp16Twin.empty()) return b->fp16Twin;
  return brickId;
}

}  // namespace mb
