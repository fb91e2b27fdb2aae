# Sanitizer and fuzzing builds (issue 16). Both are options so that the default build stays
# the plain Release one that scripts/build.sh makes; the `asan` preset turns them on.
#
# MB_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target of ours. UBSan
# does not recover, so a finding stops the program with a non-zero exit like an ASan report.
# MB_FUZZ: the libFuzzer targets of fuzz/ (clang only). The whole tree is then compiled with
# -fsanitize=fuzzer-no-link so that the loaders the fuzzers call report coverage.
option(MB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(MB_FUZZ "Build the libFuzzer targets of fuzz/ (needs clang)" OFF)

# -fno-sanitize=vptr: Debian builds glslang without RTTI, so UBSan's dynamic-type check
# cannot link against glslang::TShader (no typeinfo); every other UBSan check stays on.
if(MB_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

if(MB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "MB_FUZZ needs clang (libFuzzer); configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "or use the asan preset")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
