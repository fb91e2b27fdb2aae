#!/usr/bin/env bash
# The compile time of a fixed subset of the tree's objects, from scratch, two at a time and
# without a compiler cache (bench/README.md "Build time"). A whole clean build takes most of an
# hour on the shared 2-core VM, too long to run before and after a change; this subset is 35 of
# its ~370 objects: all of compiler/core/, seven test files, three CLI commands and ten references,
# and the precompiled headers they use (built first, and counted).
#
#   bench/build_time.sh BUILD_DIR     BUILD_DIR configured (Release, or the asan preset), any state
#
# Prints the wall and CPU seconds with the load average. The subset's objects are compiled with
# the commands ninja would run (ninja -t commands), not through ninja: ninja would first build the
# CLI that the tests' objects wait for.
set -euo pipefail
dir=$(cd "$1" && pwd)
src=$(cd "$(dirname "$0")/.." && pwd)
cd "$dir"
objs=()
for f in $(cd "$src/compiler/core" && ls *.cpp); do objs+=(CMakeFiles/mb_core.dir/compiler/core/$f.o); done
for f in main test_targets test_cli test_package test_gltf test_lut test_progress; do
  objs+=(tests/CMakeFiles/mb_tests.dir/$f.cpp.o)
done
for f in cmd_compile cmd_merge main; do objs+=(CMakeFiles/matbricks.dir/compiler/cli/$f.cpp.o); done
for f in $(cd "$src" && find shaderlib -name '*.cpp' | sort | head -10); do objs+=(CMakeFiles/mb_references.dir/$f.o); done
pchs=()
for p in CMakeFiles/mb_core.dir tests/CMakeFiles/mb_tests.dir CMakeFiles/matbricks.dir CMakeFiles/mb_references.dir; do
  for ext in gch pch; do
    if ninja -t query $p/cmake_pch.hxx.$ext >/dev/null 2>&1; then pchs+=($p/cmake_pch.hxx.$ext); fi
  done
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -f "${objs[@]}" "${pchs[@]}"
for f in "${objs[@]}" "${pchs[@]}"; do mkdir -p "$(dirname "$f")"; done
: >"$work/pch"
for p in "${pchs[@]}"; do ninja -t commands -s "$p" >>"$work/pch"; done
for o in "${objs[@]}"; do ninja -t commands -s "$o"; done >"$work/obj"
echo "${#objs[@]} objects, ${#pchs[@]} precompiled headers; start: $(uptime)"
export CCACHE_DISABLE=1
/usr/bin/time -f "wall %e s, CPU %U s user + %S s sys" -o "$work/time" bash -c "
  xargs -r -d '\n' -P2 -n1 sh -c <'$work/pch' && xargs -r -d '\n' -P2 -n1 sh -c <'$work/obj'" >"$work/log" 2>&1 \
  || { cat "$work/log"; exit 1; }
cat "$work/time"
echo "end: $(uptime)"
