// compile: HLSL to SPIR-V through glslang's HLSL front end, keeping the module that the hlsl
// target's check (target_checks.hpp) makes and validates, so that the HLSL can be run
// (validate --target hlsl; docs/targets.md "Executed"). DXC is not packaged in Debian.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mb {

// checkHlsl's reparse (entry point "main", Vulkan 1.1, spirv-val), keeping glslang's SPIR-V:
// "" and the module in `spirv`, else the first message.
std::string compileHlsl(const std::string& source, std::vector<uint32_t>& spirv, bool fragment = false);

}  // namespace mb
