# Sourced by the sanitizer scripts (tools/sanitize.sh, tools/sanitizers/tsan.sh): every finding
# stops the process with a non-zero status, so a sanitizer report always fails its test.
# UBSan is also compiled with -fno-sanitize-recover=all, so it cannot only print.
sanitizers_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1:strict_init_order=1:detect_stack_use_after_return=1:halt_on_error=1:abort_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=${sanitizers_dir}/lsan.supp:print_suppressions=0"
export TSAN_OPTIONS="halt_on_error=1:abort_on_error=1:second_deadlock_stack=1:suppressions=${sanitizers_dir}/tsan.supp"
