#!/usr/bin/env bash
# A compiler launcher that appends each compile's CPU seconds (user, sys) and its output file to
# $MB_CPU_LOG: the CPU time of a whole clean build, which the shared VM's load barely moves while
# it stretches the wall time (bench/README.md "Build time"). Used as
#
#   cmake -S . -B DIR ... -DCMAKE_CXX_COMPILER_LAUNCHER=$PWD/bench/compile_cpu.sh
#   MB_CPU_LOG=/tmp/cpu.log cmake --build DIR -j1 --target mb_tests fuzzers
#   awk '{u += $1; s += $2} END {print NR " compiles, " u " s user + " s " s sys"}' /tmp/cpu.log
set -euo pipefail
out=""
prev=""
for a in "$@"; do
  if [ "$prev" = "-o" ]; then out="$a"; fi
  prev="$a"
done
exec /usr/bin/time -a -o "${MB_CPU_LOG:?set MB_CPU_LOG to the log file}" -f "%U %S $out" "$@"
