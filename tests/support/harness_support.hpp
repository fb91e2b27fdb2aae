// Shared by tests that run kernels on the Vulkan harness.
#pragma once
#include <cstdlib>

#include "harness/vulkan_harness.hpp"

namespace mb::harness {

// Default device (lavapipe under CTest), with the validation layer on whenever the test
// environment sets MATBRICKS_VALIDATION (tests/CMakeLists.txt does).
inline DeviceOptions testDeviceOptions() {
  DeviceOptions options;
  options.validation = std::getenv("MATBRICKS_VALIDATION") != nullptr;
  return options;
}

}  // namespace mb::harness
