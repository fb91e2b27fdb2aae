#include "compile/engine_includes.hpp"

#include <algorithm>
#include <regex>
#include <set>

#include "compile/glsl_compiler.hpp"
#include "compile/target_checks.hpp"
#include "compile/targets.hpp"
#include "core/diagnostics.hpp"
#include "core/light_type.hpp"
#include "emit/light_contract.hpp"

namespace mb {
namespace {

[[noreturn]] void fail(const std::string& displayName, const std::string& target, const std::string& why) {
  throw DiagnosticError({{Severity::Error, "E-TARGET-FAILED", {displayName, 0, 0}, target + " include: " + why}});
}

// The language of a target's include (only hlsl and msl have includes of their own).
IncludeLanguage includeLanguageOf(Target target) {
  switch (targetInfo(target).language) {
    case TargetLanguage::Hlsl:
      return IncludeLanguage::Hlsl;
    case TargetLanguage::Msl:
      return IncludeLanguage::Msl;
    default:
      return IncludeLanguage::Glsl;
  }
}

std::set<std::string> structNames(const std::string& code) {
  static const std::regex kStruct(R"(\bstruct\s+(\w+))");
  std::set<std::string> out;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), kStruct); it != std::sregex_iterator(); ++it)
    out.insert((*it)[1]);
  return out;
}

std::string localName(const std::string& type) {
  std::string s = "mb_";
  for (char c : type) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

// How a language converts a value to a type: GLSL and MSL construct, HLSL casts.
std::string convert(IncludeLanguage lang, const std::string& type, const std::string& value) {
  return lang == IncludeLanguage::Hlsl ? "(" + type + ")(" + value + ")" : type + "(" + value + ")";
}

// Statements that call every contract function of `code`: one local per parameter type
// (numbers from `seed`, structs filled by the calls that return them, in contract order:
// materialInputs, then preparePixel, ...), every returned radiance added to `sum`.
std::string callEveryFunction(const std::string& code, IncludeLanguage lang, const std::string& seed,
                              const std::string& sum, const std::string& indent) {
  const std::set<std::string> structs = structNames(code);
  const std::vector<FunctionSignature> fns = contractFunctions(code);
  std::set<std::string> declared;
  std::string decls, calls;
  auto local = [&](const std::string& type) {
    if (declared.insert(type).second)
      decls += indent + type + " " + localName(type) + (structs.count(type) ? "" : " = " + convert(lang, type, seed)) +
               ";\n";
    return localName(type);
  };
  const std::string vec3 = lang == IncludeLanguage::Glsl ? "vec3" : "float3";
  for (const auto& f : fns) {
    std::string args;
    for (const auto& p : f.params) args += (args.empty() ? "" : ", ") + local(bareType(p.type));
    const std::string call = f.name + "(" + args + ")";
    if (structs.count(f.returnType))
      calls += indent + local(f.returnType) + " = " + call + ";\n";
    else
      calls += indent + sum + " += " + convert(lang, vec3, call) + ";\n";
  }
  return decls + calls;
}

// Placeholder definitions of the hooks `code` declares (their values do not matter here).
std::string hookDefinitions(const std::string& code, IncludeLanguage lang) {
  std::string out;
  for (const auto& h : hookPrototypes(code))
    out += h.text + "\n{\n    return " + convert(lang, h.returnType, "0") + ";\n}\n\n";
  return out;
}

// Step 1: the shell. The emitted GLSL up to the probe, with hook bodies and a main().
std::string includeShell(const std::string& glsl) {
  std::string code = glsl.substr(0, glsl.find("#ifndef MB_NO_PROBE"));
  std::string shell = code + hookDefinitions(code, IncludeLanguage::Glsl);
  // Nothing is optimized (step 2), so uninitialized inputs fold nothing away.
  shell += "layout(local_size_x = 1) in;\nvoid main() {\n    float mbSeed;\n    vec3 mbSum = vec3(0.0);\n";
  shell += callEveryFunction(code, IncludeLanguage::Glsl, "mbSeed", "mbSum", "    ");
  return shell + "}\n";
}

bool isShellEntry(const std::string& item) {
  for (const char* name : {"main", "comp_main", "main0"})
    if (auto f = findFunction(item, name); f && f->defined) return true;
  // HLSL's [numthreads] attribute and MSL's kernel qualifier sit on the entry point itself.
  return item.find("[numthreads(") != std::string::npos || item.find("kernel void") != std::string::npos ||
         item.find("gl_WorkGroupSize") != std::string::npos || item.find("SPIRV_Cross_Input") != std::string::npos;
}

// Step 4: keep what the contract needs of SPIRV-Cross's output of the shell.
std::string extractInclude(const std::string& crossOutput) {
  std::string out;
  for (const auto& item : topLevelItems(crossOutput)) {
    if (isShellEntry(item.text)) continue;
    bool hook = false;
    for (const auto& name : fetchHookNames())
      if (auto f = findFunction(item.text, name); f && f->defined) {
        // The engine's definition replaces the shell's placeholder.
        out += f->text + ";\n\n";
        hook = true;
      }
    if (!hook) out += item.text + (item.text[0] == '#' ? "" : "\n");
  }
  return out;
}

int balance(const std::string& s, char open, char close) {
  int depth = 0;
  for (char c : s) {
    depth += c == open ? 1 : c == close ? -1 : 0;
    if (depth < 0) return -1;
  }
  return depth;
}

}  // namespace

const std::vector<std::string>& contractFunctionNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n{"materialInputs", "preparePixel", "emittedRadiance"};
    for (LightType t : allLightTypes()) n.push_back(lightEntryPoint(t));
    n.push_back("shadeEnvironment");
    n.push_back("evaluateMaterial");
    return n;
  }();
  return names;
}

const std::vector<std::string>& fetchHookNames() {
  static const std::vector<std::string> names{"mb_fetch_prefiltered",      "mb_fetch_dfg",
                                              "mb_fetch_ltc_matrix",       "mb_fetch_ltc_magnitude",
                                              "mb_fetch_ltc_sheen_matrix", "mb_fetch_ltc_sheen_magnitude"};
  return names;
}

std::vector<FunctionSignature> contractFunctions(const std::string& code) {
  std::vector<FunctionSignature> out;
  for (const auto& name : contractFunctionNames())
    if (auto f = findFunction(code, name); f && f->defined) out.push_back(*f);
  return out;
}

std::vector<std::string> missingContractFunctions(const std::string& glsl, const std::string& body) {
  const std::vector<FunctionSignature> kept = contractFunctions(body);
  std::vector<std::string> missing;
  for (const auto& f : contractFunctions(glsl.substr(0, glsl.find("#ifndef MB_NO_PROBE"))))
    if (std::none_of(kept.begin(), kept.end(), [&](const FunctionSignature& k) { return k.name == f.name; }))
      missing.push_back(f.name);
  return missing;
}

std::vector<FunctionSignature> hookPrototypes(const std::string& code) {
  std::vector<FunctionSignature> out;
  for (const auto& name : fetchHookNames())
    if (auto f = findFunction(code, name); f && !f->defined) out.push_back(*f);
  return out;
}

std::map<std::string, std::string> crossCompileIncludes(const std::string& glsl, const std::vector<Target>& targets,
                                                        const std::string& displayName) {
  std::map<std::string, std::string> out;
  std::vector<Target> wanted;  // in package order
  for (Target t : allTargets())
    if (*targetInfo(t).includeExtension && std::find(targets.begin(), targets.end(), t) != targets.end())
      wanted.push_back(t);
  if (wanted.empty()) return out;
  CompileOptions noInlining;
  noInlining.optimization = OptimizationLevel::O0;
  const std::string shellName = displayName + " (include shell)";
  const std::vector<uint32_t> spirv = compileComputeGlsl(includeShell(glsl), shellName, noInlining).spirv;
  for (Target target : wanted) {
    const std::string& name = targetName(target);
    const IncludeLanguage lang = includeLanguageOf(target);
    // crossCompile sets the target's own options and checks the whole shell's output.
    const std::string body = extractInclude(crossCompile(spirv, target, shellName));
    for (const auto& fn : missingContractFunctions(glsl, body))
      fail(displayName, name, "contract function '" + fn + "' is missing");
    const std::string wrapper = includeWrapper(body, lang);
    const std::string problem = lang == IncludeLanguage::Hlsl ? checkHlsl(wrapper, true) : checkMslInclude(wrapper);
    if (!problem.empty()) fail(displayName, name, problem);
    out[name] = body;
  }
  return out;
}

std::string includeWrapper(const std::string& body, IncludeLanguage language) {
  std::string s = body + hookDefinitions(body, language);
  if (language == IncludeLanguage::Hlsl) {
    s += "float4 main(float4 mbPosition : SV_Position) : SV_Target\n{\n    float mbSeed = mbPosition.x;\n"
         "    float3 mbSum = (float3)0;\n";
    s += callEveryFunction(body, language, "mbSeed", "mbSum", "    ");
  } else {
    s += "fragment float4 mbWrapperMain(float4 mbPosition [[position]])\n{\n    float mbSeed = mbPosition.x;\n"
         "    float3 mbSum = float3(0.0);\n";
    s += callEveryFunction(body, language, "mbSeed", "mbSum", "    ");
  }
  return s + "    return float4(mbSum, 1.0);\n}\n";
}

std::string checkMslInclude(const std::string& wrapper) {
  for (const auto& [open, close] : {std::pair{'{', '}'}, std::pair{'(', ')'}, std::pair{'[', ']'}})
    if (balance(wrapper, open, close) != 0) return std::string("MSL: unbalanced '") + open + close + "'";
  if (wrapper.find("#include <metal_stdlib>") == std::string::npos) return "MSL: no #include <metal_stdlib>";
  const std::vector<SourceItem> items = topLevelItems(wrapper);
  auto count = [&](const std::string& name, bool defined) {
    return std::count_if(items.begin(), items.end(), [&](const SourceItem& i) {
      auto f = findFunction(i.text, name);
      return f && f->defined == defined;
    });
  };
  for (const auto& name : contractFunctionNames())
    if (count(name, true) > 1 || count(name, false) > 0)
      return "MSL: contract function '" + name + "' is not defined exactly once";
  for (const auto& name : fetchHookNames())
    if (count(name, false) != count(name, true) || count(name, true) > 1)
      return "MSL: hook '" + name + "' is not declared once by the include and defined once by the wrapper";
  const auto entries = std::count_if(items.begin(), items.end(), [](const SourceItem& i) {
    return i.text.rfind("fragment ", 0) == 0 || i.text.find("kernel ") != std::string::npos;
  });
  if (entries != 1) return "MSL: expected one fragment entry point, found " + std::to_string(entries);
  return "";
}

}  // namespace mb
