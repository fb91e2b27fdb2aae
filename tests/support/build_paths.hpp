// Paths of this build (the source tree, the CLI, the C++ compiler), compiled into one generated
// file (tests/CMakeLists.txt) rather than into every test object: the objects then stay the same
// in any checkout and build directory, so a compiler cache shares them between worktrees.
#pragma once
#include <filesystem>
#include <string>

namespace mb::test {

std::filesystem::path buildSourceDir();  // the source tree the tests were built from
std::filesystem::path fuzzDir();         // <source>/fuzz
std::string cliPath();                   // the matbricks binary of this build
std::string cxxCompiler();               // CMAKE_CXX_COMPILER

}  // namespace mb::test
