// Catch2 entry point. The test environment (lavapipe, validation layer on, path of the CLI)
// is set here rather than through CTest's ENVIRONMENT property: catch_discover_tests passes
// properties through a ';'-separated list and silently kept only the first assignment, which
// left the validation layer off. An explicit environment from the caller still wins.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>

int main(int argc, char* argv[]) {
  ::setenv("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 0);
  ::setenv("MATBRICKS_VALIDATION", "1", 0);
  ::setenv("MATBRICKS_CLI", MB_CLI_PATH, 0);
  return Catch::Session().run(argc, argv);
}
