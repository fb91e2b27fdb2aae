// Catch2 entry point. The test environment (lavapipe, validation layer on, path of the CLI)
// is set here rather than through CTest's ENVIRONMENT property: catch_discover_tests passes
// properties through a ';'-separated list and silently kept only the first assignment, which
// left the validation layer off. An explicit environment from the caller still wins.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "support/build_paths.hpp"

int main(int argc, char* argv[]) {
  ::setenv("VK_ICD_FILENAMES", "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json", 0);
  ::setenv("MATBRICKS_VALIDATION", "1", 0);
  ::setenv("MATBRICKS_CLI", mb::test::cliPath().c_str(), 0);
  // Compiles in tests (and the CLI runs they start) use a cache of their own, never the
  // user's ~/.cache/matbricks: one directory per test process, removed when it ends. Tests of
  // concurrent cache use make their own shared directory.
  const auto cache = std::filesystem::temp_directory_path() / ("matbricks-test-cache-" + std::to_string(::getpid()));
  ::setenv("MATBRICKS_CACHE_DIR", cache.c_str(), 0);
  // Nor a team's remote cache: the remote-cache tests start their own server.
  ::unsetenv("MATBRICKS_CACHE_URL");
  int rc = Catch::Session().run(argc, argv);
  std::error_code ec;
  std::filesystem::remove_all(cache, ec);
  return rc;
}
