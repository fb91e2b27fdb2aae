#include "compile/glsl_declarations.hpp"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include "compile/glslang_setup.hpp"

namespace mb {
namespace {

std::string fileOf(const glslang::TSourceLoc& loc) {
  const char* name = loc.getFilename();
  return name && *name ? name : "the generated code";
}

// Functions are visited as their definitions (EOpFunction, named "name(mangled args;"); every
// global (used or not) sits in the linker objects node that parse() appends to the tree
// (TIntermediate::addSymbolLinkageNodes). Struct and block type names come from the types of
// every symbol met, including function parameters: a struct no symbol has is not seen, and
// then no generated code uses it either.
class GlobalCollector : public glslang::TIntermTraverser {
 public:
  explicit GlobalCollector(std::map<std::string, std::string>& out) : out_(out) {}

  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* node) override {
    if (node->getOp() == glslang::EOpFunction) {
      std::string name(node->getName().c_str());
      name = name.substr(0, name.find('('));
      add(name, "a function of " + fileOf(node->getLoc()));
      typeNames(node->getType(), node->getLoc());
    }
    if (node->getOp() == glslang::EOpLinkerObjects) inLinkerObjects_ = true;
    return true;
  }

  void visitSymbol(glslang::TIntermSymbol* symbol) override {
    const glslang::TType& type = symbol->getType();
    typeNames(type, symbol->getLoc());
    if (!inLinkerObjects_) return;
    std::string name(symbol->getName().c_str());
    if (name.rfind("anon@", 0) == 0 && type.isStruct()) {
      // An anonymous block's members are globals themselves (GLSL 4.50 spec 4.3.9).
      for (const auto& member : *type.getStruct())
        add(member.type->getFieldName().c_str(), "a global of " + fileOf(symbol->getLoc()));
      return;
    }
    add(name, std::string(type.getQualifier().storage == glslang::EvqConst ? "a constant" : "a global") + " of " +
                  fileOf(symbol->getLoc()));
  }

 private:
  void typeNames(const glslang::TType& type, const glslang::TSourceLoc& loc) {
    if (!type.isStruct()) return;
    std::string name(type.getTypeName().c_str());
    if (!name.empty() && !out_.count(name)) {
      add(name, (type.getBasicType() == glslang::EbtBlock ? "an interface block of " : "a struct of ") + fileOf(loc));
      for (const auto& member : *type.getStruct()) typeNames(*member.type, loc);
    }
  }
  void add(const std::string& name, const std::string& what) {
    if (!name.empty() && name.rfind("gl_", 0) != 0) out_.emplace(name, what);
  }

  std::map<std::string, std::string>& out_;
  bool inLinkerObjects_ = false;
};

}  // namespace

std::optional<std::map<std::string, std::string>> glslGlobalDeclarations(const std::string& source, ShaderStage stage) {
  ensureGlslangInitialized();
  const EShLanguage language = glslangLanguage(stage);
  glslang::TShader shader(language);
  const char* text = source.c_str();
  shader.setStrings(&text, 1);
  setVulkanEnvironment(shader, language);
  if (!shader.parse(GetDefaultResources(), 450, false, kVulkanMessages)) return std::nullopt;
  std::map<std::string, std::string> out;
  GlobalCollector collector(out);
  if (TIntermNode* root = shader.getIntermediate()->getTreeRoot()) root->traverse(&collector);
  return out;
}

}  // namespace mb
