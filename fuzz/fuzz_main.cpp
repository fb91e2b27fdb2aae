// One libFuzzer binary per target: MB_FUZZ_TARGET names the body in targets/fuzz_targets.cpp.
// A FuzzFinding escapes and terminates the process, which libFuzzer reports as a crash and
// saves as an artifact (scripts/fuzz.sh keeps it under fuzz/findings/).
#include <cstddef>
#include <cstdint>

#include "targets/fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const mb::fuzz::Target& target = mb::fuzz::target(MB_FUZZ_TARGET);
  target.run(data, size);
  return 0;
}
