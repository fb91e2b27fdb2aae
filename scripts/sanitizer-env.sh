# Sourced by scripts/fuzz.sh and scripts/sanitize.sh: the sanitizer options of the asan preset
# (CMakePresets.json's asan test preset sets the same). Leaks inside the Vulkan driver and its
# LLVM are suppressed by tests/sanitizers/lsan.supp; ours are not.
_mb_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$_mb_root/tests/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$_mb_root/tests/sanitizers/ubsan.supp"
unset _mb_root
