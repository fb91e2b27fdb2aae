# Precompiled headers (bench/README.md "Build time"). A clean build spends much of its time
# parsing the same third-party headers again in every object: nlohmann/json.hpp is in most of
# compiler/ and the tests, catch2/catch.hpp in every test file, CLI11 in every CLI command, and
# <filesystem>, <regex> and friends nearly everywhere. Only third-party and standard headers
# are precompiled, never one of ours: a header of compiler/ in a PCH would reach every object
# without an #include, which the layer check (cmake/CheckLayers.cmake, reading the #include
# lines) could not see. Every source still includes what it uses, so the tree builds the same
# with -DMB_PCH=OFF (or CMake's -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON).
#
#   mb_compiler_pch(<target>)   the PCH of compiler/: built once, with the first layer (mb_core),
#                               and reused by every target compiled with the same flags (every
#                               layer, the benchmark programs, the fuzz targets)
#   mb_own_pch(<target> <header>...)   a PCH of its own: the compiler PCH's headers and <header>...
#   mb_pch(<target> <header>...)       a PCH of its own of just <header>...
#
# A compiler cache needs to be told about PCHs: see MB_CCACHE_SLOPPINESS below.
#
# MB_PCH (default: on with Clang, off with GCC) turns them on. With GCC 12 a PCH gains little
# and costs warnings: its middle-end warnings about libstdc++'s own code (-Wstringop-overflow,
# -Wstringop-overread, -Warray-bounds on `"literal" + std::string` inlined at -O3), silent
# without a PCH because they point into a system header, are all reported when <string> comes
# from a PCH, and at -O3 parsing is a small part of an object's compile (bench/README.md
# "Build time": 10 % of the CPU time of the measured subset). Clang (the asan preset) has no
# such warnings, and there a PCH saves 1-3 s of CPU per object.
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(mb_pch_default ON)
else()
  set(mb_pch_default OFF)
endif()
option(MB_PCH "Precompile the third-party and standard headers (cmake/Precompiled.cmake)" ${mb_pch_default})
if(CMAKE_DISABLE_PRECOMPILE_HEADERS)
  set(MB_PCH OFF)
endif()

# Standard headers that more than a handful of compiler/ sources include, and nlohmann/json.
set(MB_PCH_HEADERS
    <algorithm> <array> <atomic> <chrono> <cmath> <cstdint> <cstdio> <cstring> <filesystem>
    <fstream> <functional> <map> <memory> <mutex> <optional> <set> <sstream> <stdexcept> <string>
    <string_view> <thread> <tuple> <unordered_map> <utility> <vector> <nlohmann/json.hpp>)

function(mb_compiler_pch target)
  if(NOT MB_PCH)
    return()
  endif()
  get_property(owner GLOBAL PROPERTY MB_COMPILER_PCH_TARGET)
  if(owner)
    target_precompile_headers(${target} REUSE_FROM ${owner})
  else()
    target_precompile_headers(${target} PRIVATE ${MB_PCH_HEADERS})
    set_property(GLOBAL PROPERTY MB_COMPILER_PCH_TARGET ${target})
  endif()
endfunction()

function(mb_own_pch target)
  mb_pch(${target} ${MB_PCH_HEADERS} ${ARGN})
endfunction()

function(mb_pch target)
  if(MB_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# ccache and PCHs (ccache(1) "PRECOMPILED HEADERS"): it caches an object compiled against a PCH
# only with sloppiness pch_defines and time_macros (it cannot see the macros a PCH defines), and
# include_file_mtime/ctime keep a just-written PCH from disabling the direct mode. ccache hashes
# the PCH an object uses, and a PCH need not be the same bytes from one compile to the next
# (GCC's .gch is not), so in a fresh build directory objects hit only if the PCH's own compile
# did, which it does (bench/README.md "Build time"). These settings are
# passed to each compile through the environment, added to whatever sloppiness the user's
# ccache.conf already has, so nothing needs configuring by hand.
set(MB_CCACHE_SLOPPINESS pch_defines time_macros include_file_mtime include_file_ctime)
function(mb_ccache_for_pch)
  if(NOT MB_PCH OR NOT CMAKE_CXX_COMPILER_LAUNCHER)
    return()
  endif()
  list(GET CMAKE_CXX_COMPILER_LAUNCHER 0 launcher)
  get_filename_component(launcher_name ${launcher} NAME)
  if(NOT launcher_name STREQUAL "ccache")
    return()
  endif()
  execute_process(COMMAND ${launcher} --get-config sloppiness OUTPUT_VARIABLE configured
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  string(REPLACE "," ";" configured "${configured}")
  string(REPLACE " " "" configured "${configured}")
  set(sloppiness ${configured} ${MB_CCACHE_SLOPPINESS})
  list(REMOVE_ITEM sloppiness "")
  list(REMOVE_DUPLICATES sloppiness)
  list(JOIN sloppiness "," sloppiness)
  # A normal variable over the cache entry: the targets created after this take it, and the
  # cache keeps what the user gave.
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_SLOPPINESS=${sloppiness}
      ${CMAKE_CXX_COMPILER_LAUNCHER} PARENT_SCOPE)
endfunction()
mb_ccache_for_pch()

# Clang stamps the headers' modification times into a .pch unless told not to, and ccache
# refuses to cache against such a PCH. Given with or without a cache, so that the compile
# commands do not depend on the launcher.
if(MB_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  add_compile_options(-Xclang -fno-pch-timestamp)
endif()
