#include "compile/glsl_compiler.hpp"

#include <chrono>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "compile/glslang_setup.hpp"

namespace mb {
namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

constexpr auto kTargetEnv = SPV_ENV_VULKAN_1_1;

// Maps (file, line) of the emitted source, as its #line directives define them, to the text
// of that line, so a diagnostic can name a column (glslang 12 reports none).
class LineMap {
 public:
  LineMap(const std::string& source, const std::string& displayName) {
    std::istringstream in(source);
    std::string text, file = displayName;
    int line = 1;
    static const std::regex lineDirective(R"(^\s*#\s*line\s+(\d+)(?:\s+\"([^\"]*)\")?)");
    while (std::getline(in, text)) {
      std::smatch m;
      if (std::regex_search(text, m, lineDirective)) {
        line = std::stoi(m[1].str());
        if (m[2].matched) file = m[2].str();
        continue;
      }
      lines_[{file, line}] = text;
      ++line;
    }
  }
  const std::string* find(const std::string& file, int line) const {
    auto it = lines_.find({file, line});
    return it == lines_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::pair<std::string, int>, std::string> lines_;
};

// Turns glslang's info log ("ERROR: file:line: 'tok' : message") into diagnostics.
std::vector<Diagnostic> parseInfoLog(const std::string& log, const LineMap& lines, const std::string& displayName) {
  std::vector<Diagnostic> out;
  std::istringstream in(log);
  std::string text;
  static const std::regex entry(R"(^(ERROR|WARNING): (.*):(\d+): (.*)$)");
  static const std::regex quoted(R"('([^']+)')");
  while (std::getline(in, text)) {
    std::smatch m;
    if (!std::regex_match(text, m, entry)) {
      // Summary lines such as "ERROR: 1 compilation errors.  No code generated." add nothing.
      continue;
    }
    std::string body = m[4].str();
    while (!body.empty() && body.back() == ' ') body.pop_back();
    // glslang follows a fatal error with "'' : compilation terminated": it adds nothing.
    if (body.find("compilation terminated") != std::string::npos) continue;
    Diagnostic d;
    d.severity = m[1] == "ERROR" ? Severity::Error : Severity::Warning;
    d.code = "E-GLSL";
    d.where.file = m[2].str() == "0" ? displayName : m[2].str();
    d.where.line = std::stoi(m[3].str());
    d.message = "GLSL: " + body;
    d.where.column = 1;
    std::smatch q;
    if (std::regex_search(body, q, quoted)) {
      if (const std::string* src = lines.find(d.where.file, d.where.line)) {
        auto pos = src->find(q[1].str());
        if (pos != std::string::npos) d.where.column = static_cast<int>(pos) + 1;
      }
    }
    if (d.severity == Severity::Error) out.push_back(d);
  }
  if (out.empty()) {
    out.push_back({Severity::Error, "E-GLSL", {displayName, 0, 0}, "GLSL: " + log, ""});
  }
  return out;
}

std::vector<uint32_t> frontEnd(const std::string& source, const std::string& displayName, ShaderStage stage,
                               CompileStageTimes& times) {
  ensureGlslangInitialized();
  auto t0 = Clock::now();
  const EShLanguage language = glslangLanguage(stage);
  glslang::TShader shader(language);
  const char* text = source.c_str();
  const char* name = displayName.c_str();
  shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
  setVulkanEnvironment(shader, language);
  const auto messages = kVulkanMessages;
  if (!shader.parse(GetDefaultResources(), 450, false, messages)) {
    throw DiagnosticError(parseInfoLog(shader.getInfoLog(), LineMap(source, displayName), displayName));
  }
  times.parseMs = msSince(t0);
  auto t1 = Clock::now();
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    throw DiagnosticError(
        {{Severity::Error, "E-GLSL-LINK", {displayName, 0, 0}, std::string("GLSL link: ") + program.getInfoLog(), ""}});
  }
  times.linkMs = msSince(t1);
  auto t2 = Clock::now();
  glslang::SpvOptions options;
  options.disableOptimizer = true;  // spirv-opt runs below, with the performance recipe
  options.generateDebugInfo = false;
  std::vector<uint32_t> spirv;
  spv::SpvBuildLogger logger;
  glslang::GlslangToSpv(*program.getIntermediate(language), spirv, &logger, &options);
  times.codegenMs = msSince(t2);
  return spirv;
}

// spirv-val; on failure, the validator's messages. Friendly names make the messages readable
// ("%float", "%MbIn") but cost most of the validator's time: it names every id of the module
// before checking the first one.
bool spirvValid(const std::vector<uint32_t>& spirv, spv_target_env env, bool friendlyNames, std::string* messages,
                bool firstOnly) {
  spvtools::SpirvTools tools(env);
  tools.SetMessageConsumer([&](spv_message_level_t, const char*, const spv_position_t& pos, const char* msg) {
    if (!messages) return;
    if (firstOnly)
      *messages = messages->empty() ? std::string(msg) : *messages;
    else
      *messages += "[word " + std::to_string(pos.index) + "] " + msg + "; ";
  });
  spvtools::ValidatorOptions options;
  options.SetFriendlyNames(friendlyNames);
  return tools.Validate(spirv.data(), spirv.size(), options);
}

void validateSpirv(const std::vector<uint32_t>& spirv, const std::string& displayName, const char* stage,
                   CompilePipeline pipeline) {
  const std::string messages = spirvValidationErrors(spirv, kTargetEnv, pipeline);
  if (messages.empty()) return;
  throw DiagnosticError({{Severity::Error,
                          "E-SPIRV-VAL",
                          {displayName, 0, 0},
                          std::string("spirv-val rejected the module ") + stage + ": " + messages,
                          ""}});
}

std::vector<uint32_t> optimizeSpirv(const std::vector<uint32_t>& spirv, const std::string& displayName,
                                    const CompileOptions& options) {
  // spvtools::Optimizer is single-use: one per compile.
  spvtools::Optimizer optimizer(kTargetEnv);
  std::string messages;
  optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* msg) {
    if (level <= SPV_MSG_ERROR) messages += std::string(msg) + "; ";
  });
  if (options.optimization == OptimizationLevel::O2) {
    optimizer.RegisterPerformancePasses();
  } else if (!optimizer.RegisterPassesFromFlags(o1PassFlags())) {
    throw std::logic_error("spirv-opt does not know an O1 flag: " + messages);
  }
  std::vector<uint32_t> optimized;
  bool ok = false;
  if (options.pipeline == CompilePipeline::Legacy) {
    ok = optimizer.Run(spirv.data(), spirv.size(), &optimized);  // validates its input again, friendly names on
  } else {
    // The input was just validated (validate on); without validation the optimizer still
    // checks its input itself, as the passes assume a valid module.
    spvtools::ValidatorOptions validatorOptions;
    validatorOptions.SetFriendlyNames(false);
    spvtools::OptimizerOptions optimizerOptions;
    optimizerOptions.set_run_validator(!options.validate);
    optimizerOptions.set_validator_options(validatorOptions);
    ok = optimizer.Run(spirv.data(), spirv.size(), &optimized, optimizerOptions);
  }
  if (!ok)
    throw DiagnosticError({{Severity::Error, "E-SPIRV-OPT", {displayName, 0, 0}, "spirv-opt failed: " + messages, ""}});
  return optimized;
}

}  // namespace

// glslang must be initialized once per process (the ~130 ms first-compile cost is paid once).
// InitializeProcess is not safe to race (glslang PR #2801, shaderc #1059), hence call_once;
// after it, TShader/TProgram/GlslangToSpv run concurrently on separate threads, each with its
// own thread-local pool allocator (glslang issue #2438). FinalizeProcess is never called: the
// symbol tables live until exit.
void ensureGlslangInitialized() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

CompileResult compileComputeGlsl(const std::string& source, const std::string& displayName,
                                 const CompileOptions& options) {
  CompileResult result;
  CompileStageTimes& times = result.stages;
  auto t0 = Clock::now();
  std::vector<uint32_t> spirv = frontEnd(source, displayName, options.stage, times);
  result.frontEndMs = msSince(t0);

  auto t1 = Clock::now();
  if (options.validate) {
    validateSpirv(spirv, displayName, "after glslang", options.pipeline);
    times.validateMs = msSince(t1);
  }
  if (options.optimization != OptimizationLevel::O0) {
    auto t2 = Clock::now();
    spirv = optimizeSpirv(spirv, displayName, options);
    times.optimizeMs = msSince(t2);
    if (options.validate) {
      auto t3 = Clock::now();
      // Kept although the input was valid: spirv-opt has emitted invalid modules (the fp16
      // constant folding of v2023.1, build.cpp), and this is what catches that.
      validateSpirv(spirv, displayName, "after spirv-opt", options.pipeline);
      times.validateOptimizedMs = msSince(t3);
    }
  }
  result.optimizeMs = msSince(t1);
  result.spirv = std::move(spirv);
  return result;
}

std::string spirvValidationErrors(const std::vector<uint32_t>& spirv, int env, CompilePipeline pipeline,
                                  bool firstOnly) {
  const auto target = static_cast<spv_target_env>(env);
  const bool legacy = pipeline == CompilePipeline::Legacy;
  std::string messages;
  if (spirvValid(spirv, target, legacy, legacy ? &messages : nullptr, firstOnly)) return "";
  // Lean: validity does not depend on the names, only the messages do.
  if (!legacy) spirvValid(spirv, target, true, &messages, firstOnly);
  return messages.empty() ? "invalid module" : messages;
}

const std::vector<std::string>& o1PassFlags() {
  // No inlining: inlining every call and then cleaning the inlined module up is where the
  // performance recipe's time goes (docs/performance-compile.md, breakdown and recipes), and
  // every driver inlines on its own. Within each function: drop unreachable functions, turn
  // local variables into SSA values and remove what is then dead.
  static const std::vector<std::string> flags{"--eliminate-dead-functions", "--eliminate-local-single-block",
                                              "--eliminate-local-single-store", "--ssa-rewrite",
                                              "--eliminate-dead-code-aggressive"};
  return flags;
}

std::string optimizationCacheToken(OptimizationLevel level) {
  switch (level) {
    case OptimizationLevel::O0:
      return "no-optimize";
    case OptimizationLevel::O1: {
      std::string token = "optimize-O1";
      for (const auto& f : o1PassFlags()) token += " " + f;
      return token;
    }
    case OptimizationLevel::O2:
      break;
  }
  return "optimize";
}

std::string toolchainVersion() {
  std::ostringstream s;
  s << "glslang " << GLSLANG_VERSION_MAJOR << "." << GLSLANG_VERSION_MINOR << "." << GLSLANG_VERSION_PATCH
    << GLSLANG_VERSION_FLAVOR << "; " << spvSoftwareVersionString();
  return s.str();
}

size_t spirvInstructionCount(const std::vector<uint32_t>& spirv) {
  size_t count = 0;
  for (size_t i = 5; i < spirv.size();) {  // 5-word header
    uint32_t words = spirv[i] >> 16;
    if (words == 0) break;
    i += words;
    ++count;
  }
  return count;
}

}  // namespace mb
