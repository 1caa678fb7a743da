#!/usr/bin/env bash
# ThreadSanitizer over everything that runs two threads: the ring buffer suite (line memory
# stress, drain, the stylus drain), the LMC device against its in-process emulated board (flow
# control, abort from every state, unplug, framing until abort, the stop sequence with each
# command failing, the settings every list re-sends), and from the engine the job
# runner's threaded paths — real-time jobs, stop requests from another thread, command-level jobs
# with their abort watcher, Ctrl-C (SIGINT through the command line's InterruptScope, in-process;
# marker_threads_tests) — each repeated, so a rare interleaving has several chances to show.
# TSan fails the run on the first data race.
# Usage: scripts/tsan.sh [build-dir] [repeats] (default build-tsan, 3).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$src/build-tsan}"
repeats="${2:-3}"
# -O1 with line tables only (GCC -g1): reports keep file:line, and a file compiles in ~40 % less
# time than with -O2 -g (17.0 s vs 10.6 s for mark_command.cpp); CI builds the engine three times.
cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMARKER_TSAN=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DMARKER_BENCH=OFF >/dev/null
ninja -C "$build" ringbuffer_tests driver_tests marker_threads_tests
# halt_on_error: the first race fails the run; second_deadlock_stack for readable reports.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
"$build/tests/ringbuffer_tests" --gtest_repeat="$repeats" --gtest_brief=1
"$build/tests/driver_tests" --gtest_repeat="$repeats" --gtest_brief=1 \
  --gtest_filter='LmcDevice.*:LmcSettingsResent.*:*LmcStopSequence*:LmcMaskedLink.*'
"$build/tests/marker_threads_tests" --gtest_repeat="$repeats" --gtest_brief=1 \
  --gtest_filter='JobSafety.*:JobEndToEnd.RealTime*:DeviceProgram.*:InterruptScope.*'
echo "tsan: clean over $repeats runs of the threaded tests"
