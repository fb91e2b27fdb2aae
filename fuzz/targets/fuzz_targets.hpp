// The bodies of the libFuzzer targets (docs/fuzzing.md). Each takes one input's bytes, runs
// it through a loader the way the CLI would, and throws FuzzFinding when the loader breaks a
// rule of docs/bad-inputs.md: anything but success or a DiagnosticError whose errors all carry
// a code and a file. Crashes, sanitizer reports and hangs are found by the fuzzer itself.
//
// The same functions run in two places: fuzz/fuzz_main.cpp wraps one in LLVMFuzzerTestOneInput
// (clang, -fsanitize=fuzzer), and tests/test_fuzz_regressions.cpp replays every kept finding and
// seed through them in the normal build.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mb::fuzz {

// A broken rule: an exception other than DiagnosticError, or an error without code or file.
class FuzzFinding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

// The oracle every target applies: runs `load`; returns when it succeeds or throws a
// DiagnosticError whose errors all have an E- code and a file; throws FuzzFinding otherwise.
void expectLoadOrDiagnostics(const std::function<void()>& load);

using TargetFunction = void (*)(const uint8_t* data, size_t size);

struct Target {
  const char* name;  // fuzz/regressions/<name>/, fuzz/seeds.txt, the binary mb_fuzz_<name>
  TargetFunction run;
};

// material_json, material_macro, gltf, scene, csv.
const std::vector<Target>& targets();
const Target& target(const std::string& name);

}  // namespace mb::fuzz
