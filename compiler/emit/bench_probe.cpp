#include "emit/bench_probe.hpp"

#include <stdexcept>

#include "emit/glsl_writer.hpp"

namespace mb {
namespace {

// A record input's GLSL type: toString's names are GLSL's for float, vec2 and vec3.
std::string glslTypeName(ValueType t) {
  if (t == ValueType::Geometry)  // never a record input: n, v, l are
    throw std::logic_error("bench probe: a record input cannot be a Geometry");
  return toString(t);
}

std::string recordRead(const ProbeInput& in) {
  auto at = [&](uint32_t k) { return "mbIn[b + " + std::to_string(in.offset + k) + "u]"; };
  int n = componentCount(in.type);
  if (n == 1) return at(0);
  std::string s = glslTypeName(in.type) + "(";
  for (int k = 0; k < n; ++k) s += (k ? ", " : "") + at(static_cast<uint32_t>(k));
  return s + ")";
}

// The probe's entry point is renamed rather than cut out, so the text above the appended
// entry point is byte for byte what validate compiles, and the kernel interface it declares
// (local size, the two buffers, the push constant: the harness contract) is the one the
// bench entry point uses. The renamed function is never called, so spirv-opt drops it.
// "#line 2" keeps the numbering of every following line as it was.
std::string withProbeEntryRenamed(const std::string& glsl) {
  size_t eol = glsl.find('\n');
  if (glsl.rfind("#version", 0) != 0 || eol == std::string::npos || glsl.find("void main()") == std::string::npos)
    throw std::logic_error("bench probe: emitted probe lacks #version or its main()");
  return glsl.substr(0, eol + 1) + "#define main mbValidationProbeMain\n#line 2\n" + glsl.substr(eol + 1);
}

// Appends the timing entry point; `callExpr` uses the perturbed inputs p_<name>.
EmittedShader withBenchEntry(EmittedShader s, const std::string& callExpr, const BenchProbeOptions& o) {
  const ProbeLayout& layout = s.layout;
  const std::string iterations = std::to_string(o.iterations) + "u";
  std::string body = withProbeEntryRenamed(s.glsl);
  GlslWriter w(s.fileName);
  w.line(std::string("// Bench entry point (") + (o.baseline ? "baseline: empty loop" : "timed call") + "), " +
         iterations + " evaluations per record; see compiler/emit/bench_probe.hpp.");
  w.line("#undef main");
  w.line("void main() {");
  w.line("    uint i = gl_GlobalInvocationID.x;");
  w.line("    if (i >= mbPush.count) return;");
  w.line("    uint b = i * " + std::to_string(layout.inStride) + "u;");
  for (const auto& in : layout.inputs)
    w.line(std::string("    ") + glslTypeName(in.type) + " q_" + in.name + " = " + recordRead(in) + ";");
  const std::string outType = glslTypeName(layout.output);
  w.line("    " + outType + " acc = " + outType + "(0.0);");
  w.line("    for (uint k = 0u; k < " + iterations + "; ++k) {");
  // 2^-20 per iteration: at most 6e-5 relative after 64 iterations, well inside every
  // domain's tolerance for "the same input", and exact in fp32 for k < 2^24.
  w.line("        float s = 1.0 - float(k) * 9.5367431640625e-07;");
  std::string sum;
  for (const auto& in : layout.inputs) {
    w.line(std::string("        ") + glslTypeName(in.type) + " p_" + in.name + " = q_" + in.name + " * s;");
    int n = componentCount(in.type);
    for (int k = 0; k < n; ++k)
      sum += (sum.empty() ? "" : " + ") + ("p_" + in.name) + (n == 1 ? "" : std::string(".") + "xyz"[k]);
  }
  w.line("        acc += " + (o.baseline ? outType + "(" + (sum.empty() ? "s" : sum) + ")" : callExpr) + ";");
  w.line("    }");
  w.line("    uint o = i * " + std::to_string(layout.outStride) + "u;");
  int n = componentCount(layout.output);
  for (int k = 0; k < n; ++k)
    w.line("    mbOut[o + " + std::to_string(k) + "u] = acc" + (n == 1 ? "" : std::string(".") + "xyz"[k]) + ";");
  w.line("}");

  // The appended lines continue the generated file's numbering: re-base them after `body`.
  size_t bodyLines = 0;
  for (char c : body) bodyLines += c == '\n';
  s.glsl = body + "#line " + std::to_string(bodyLines - 1) + "\n" + w.str();
  s.key += o.baseline ? ".bench_baseline" : ".bench";
  return s;
}

}  // namespace

EmittedShader emitBrickBenchProbe(const ShaderLibrary& lib, const Brick& brick, const BenchProbeOptions& options) {
  const Slot* slot = lib.findSlot(brick.slot);
  if (!slot) throw std::logic_error("bench probe: brick '" + brick.id + "' has no slot");
  std::string args;
  for (const auto& p : slot->params)
    args += (args.empty() ? "" : ", ") +
            (p.type == ValueType::Geometry ? std::string("makeGeometry(p_n, p_v, p_l)") : "p_" + p.name);
  return withBenchEntry(emitBrickProbe(lib, brick), brick.function + "(" + args + ")", options);
}

EmittedShader emitPermutationBenchProbe(const ShaderLibrary& lib, const Permutation& perm,
                                        const BenchProbeOptions& options) {
  EmittedShader s = emitPermutation(lib, perm);
  // The function validation's main calls (emitter.hpp): every light and the environment of the
  // permutation, on the perturbed record.
  const std::string call = permutationRadianceCall(s.layout);
  return withBenchEntry(std::move(s), call, options);
}

}  // namespace mb
