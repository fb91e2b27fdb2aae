// MB_VK_CHECK: turns a failed Vulkan call into a one-line HarnessError that names the call
// and the VkResult, so a failure reads "vkCreateDevice(...) failed: VK_ERROR_..." instead
// of a bare number. Private to compiler/harness.
#pragma once
#include <vulkan/vulkan.h>

#include <string>

#include "harness/vulkan_harness.hpp"

namespace mb::harness {

// "VK_ERROR_OUT_OF_DEVICE_MEMORY", or "VkResult(-1000)" for codes this build does not name.
inline std::string vkResultName(VkResult result) {
  switch (result) {
#define MB_VK_RESULT_CASE(r) \
  case r:                    \
    return #r;
    MB_VK_RESULT_CASE(VK_SUCCESS)
    MB_VK_RESULT_CASE(VK_NOT_READY)
    MB_VK_RESULT_CASE(VK_TIMEOUT)
    MB_VK_RESULT_CASE(VK_EVENT_SET)
    MB_VK_RESULT_CASE(VK_EVENT_RESET)
    MB_VK_RESULT_CASE(VK_INCOMPLETE)
    MB_VK_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    MB_VK_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    MB_VK_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    MB_VK_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    MB_VK_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    MB_VK_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    MB_VK_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    MB_VK_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    MB_VK_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    MB_VK_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    MB_VK_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    MB_VK_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    MB_VK_RESULT_CASE(VK_ERROR_UNKNOWN)
    MB_VK_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    MB_VK_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    MB_VK_RESULT_CASE(VK_ERROR_FRAGMENTATION)
    MB_VK_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    MB_VK_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
    MB_VK_RESULT_CASE(VK_ERROR_INVALID_SHADER_NV)
#undef MB_VK_RESULT_CASE
    default:
      return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

// Throws when `result` is an error code. Non-error codes (VK_INCOMPLETE, VK_TIMEOUT) pass:
// callers that care about them test for them explicitly.
inline void vkCheck(VkResult result, const char* call) {
  if (result < 0) {
    throw HarnessError(std::string(call) + " failed: " + vkResultName(result));
  }
}

}  // namespace mb::harness

// The stringized call is one line: the preprocessor folds the argument's newlines.
#define MB_VK_CHECK(call) ::mb::harness::vkCheck((call), #call)
