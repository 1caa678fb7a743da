#!/usr/bin/env bash
# The long serial-store kill test: KILLS (default 2000) SIGKILLs of a marking process at random
# instants, then the store is checked (no number issued twice, every issued number with exactly
# one audit row, nothing a process was told it got lost, the counter continuing after the
# highest number). CTest runs the same test with 400 kills.
#   scripts/kill-test.sh [KILLS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_BUILD:-$root/build}
[ -d "$build" ] || cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
ninja -C "$build" marker_tests >/dev/null
MARKER_KILLS=${1:-2000} "$build/tests/marker_tests" --gtest_filter='SerialStoreKill.*'
