#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer over the unit tests: the fuzz build's libraries
# (clang, -fsanitize=address,undefined, in build-fuzz/ or $MARKER_FUZZ_BUILD) link the test
# executables too, so CI compiles the engine once for both the fuzzers and this run. Any report
# fails the run (-fno-sanitize-recover=all; ASan aborts on the first error).
#   scripts/asan.sh [GTEST_FILTER]
# MARKER_ASAN_SUITES picks the test executables (default: all four); CI runs the three whose
# code is the engine's lower stages (fonts, ring buffer, devices and simulator).
# Leaks are reported only for our code: fontconfig (through cairo) keeps its caches for the
# process's life, so LeakSanitizer is told to skip its allocations (tests/asan-suppressions.txt).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}
filter=${1:-*}

CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DMARKER_FUZZ=ON -DMARKER_TESTS=ON -DMARKER_BENCH=OFF >/dev/null
read -r -a suites <<<"${MARKER_ASAN_SUITES:-fonts_tests ringbuffer_tests driver_tests marker_tests}"
ninja -C "$build" -j"$(nproc)" marker "${suites[@]}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1 ${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/tests/asan-suppressions.txt print_suppressions=0 ${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1 ${UBSAN_OPTIONS:-}"
for suite in "${suites[@]}"; do
  echo "asan: $suite"
  "$build/tests/$suite" --gtest_brief=1 --gtest_filter="$filter"
done
echo "asan: clean"
