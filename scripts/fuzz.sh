#!/usr/bin/env bash
# Coverage-guided fuzzing of the loaders (issue 16, docs/fuzzing.md).
#
#   scripts/fuzz.sh [--runs N | --seconds S] [--no-build] [target ...]
#
# Builds the libFuzzer targets of the asan preset (clang, ASan + UBSan) into build-asan/, then
# runs each named target (default: all) for N executions or S seconds, one after the other,
# from a corpus seeded with the shipped files and the kept findings, with the target's
# dictionary. A crash, sanitizer report, leak, timeout or broken diagnostic promise stops that
# target; its input is copied to fuzz/findings/<target>/ (fix it, then move it into
# fuzz/regressions/<target>/ where the tests replay it). Results go to fuzz/results.md, which
# docs/bad-inputs.md includes.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD_DIR=build-asan
LIMIT=(-runs=1000000)
LIMIT_TEXT="--runs 1000000"
BUILD=1
TARGETS=()
ALL=(material_json material_macro gltf scene csv)
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) LIMIT=(-runs="$2"); LIMIT_TEXT="--runs $2"; shift 2 ;;
    --seconds) LIMIT=(-max_total_time="$2"); LIMIT_TEXT="--seconds $2"; shift 2 ;;
    --no-build) BUILD=0; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option '$1'" >&2; exit 2 ;;
    *) TARGETS+=("$1"); shift ;;
  esac
done
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=("${ALL[@]}")

if [ "$BUILD" = 1 ]; then
  ./scripts/install-deps.sh
  [ -f "$BUILD_DIR/CMakeCache.txt" ] || cmake --preset asan
  cmake --build "$BUILD_DIR" -j "$(nproc)" --target fuzzers
fi
source ./scripts/sanitizer-env.sh

# The shipped files that seed a target (fuzz/seeds.txt).
seeds() {
  local glob f
  for glob in $(awk -v t="$1" '$1 == t { print $2 }' fuzz/seeds.txt); do
    for f in $glob; do [ -f "$f" ] && echo "$f"; done  # a directory named .json is a corpus case
  done
}

RESULTS=$(mktemp)
status=0
for t in "${TARGETS[@]}"; do
  corpus="$BUILD_DIR/fuzz-corpus/$t"
  findings="fuzz/findings/$t"
  mkdir -p "$corpus" "$findings"
  for f in $(seeds "$t") fuzz/regressions/"$t"/*; do
    [ -f "$f" ] && cp "$f" "$corpus/seed-$(basename "$f")"
  done
  log="$BUILD_DIR/fuzz-$t.log"
  echo "fuzz.sh: $t for $LIMIT_TEXT (log: $log)"
  start=$(date +%s)
  set +e
  "$BUILD_DIR/bin/mb_fuzz_$t" "${LIMIT[@]}" -dict="fuzz/dict/$t.dict" -max_len=65536 -timeout=20 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" >"$log" 2>&1
  rc=$?
  set -e
  secs=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  size=$(ls "$corpus" | wc -l)
  found=$(ls "$findings" | wc -l)
  if [ $rc -ne 0 ]; then status=1; echo "fuzz.sh: $t FOUND something (exit $rc): see $log and $findings/" >&2; tail -30 "$log" >&2; fi
  echo "| $t | ${execs:-?} | ${secs} | ${rate:-?} | ${cov:-?} | $size | $found |" >>"$RESULTS"
done

{
  echo "Run on $(date -u +%Y-%m-%d) with \`scripts/fuzz.sh $LIMIT_TEXT\` ($(nproc) cores, $(clang++ --version | head -1 | sed 's/ (.*//'), ASan + UBSan):"
  echo
  echo "| target | executions | seconds | executions/s | coverage (edges) | corpus files | open findings |"
  echo "|---|---|---|---|---|---|---|"
  cat "$RESULTS"
} >"$BUILD_DIR/fuzz-results.md"
rm -f "$RESULTS"
cat "$BUILD_DIR/fuzz-results.md"
echo "fuzz.sh: results in $BUILD_DIR/fuzz-results.md (copy to fuzz/results.md to publish them)"
exit $status
