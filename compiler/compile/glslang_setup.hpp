// How every glslang parse of ours is set up (the compile and the declaration scan read the
// same language): GLSL 450 for Vulkan 1.1, SPIR-V 1.3, Vulkan and SPIR-V rules.
#pragma once
#include <glslang/Public/ShaderLang.h>

#include "compile/glsl_compiler.hpp"

namespace mb {

inline EShLanguage glslangLanguage(ShaderStage stage) {
  return stage == ShaderStage::Fragment ? EShLangFragment
         : stage == ShaderStage::Vertex ? EShLangVertex
                                        : EShLangCompute;
}

inline void setVulkanEnvironment(glslang::TShader& shader, EShLanguage language) {
  shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
}

inline constexpr EShMessages kVulkanMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

}  // namespace mb
