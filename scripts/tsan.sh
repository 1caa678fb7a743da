#!/usr/bin/env bash
# Builds the ringbuffer test suite with ThreadSanitizer and runs it: the line-memory stress
# test and the drain tests exercise the producer/consumer pair and the drain thread, and TSan
# fails the run on any data race. Usage: scripts/tsan.sh [build-dir] (default build-tsan).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$src/build-tsan}"
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMARKER_TSAN=ON \
  -DMARKER_BENCH=OFF >/dev/null
ninja -C "$build" ringbuffer_tests
# halt_on_error: the first race fails the run; second_deadlock_stack for readable reports.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}" \
  "$build/tests/ringbuffer_tests"
