#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer over the unit tests: the fuzz build's libraries
# (clang, -fsanitize=address,undefined, in build-fuzz/ or $MARKER_FUZZ_BUILD) link the test
# executables too, so CI compiles the engine once for both the fuzzers and this run. Any report
# fails the run (-fno-sanitize-recover=all; ASan aborts on the first error).
#   scripts/asan.sh [GTEST_FILTER]
# MARKER_ASAN_SUITES picks the test executables (default: all four). Each runs in
# MARKER_ASAN_SHARDS processes at once (gtest sharding, default 2). marker_tests, without a filter, leaves
# out the tests listed in tests/asan-slow-tests.txt: the ones that take 5 s or more each under
# ASan (end-to-end command lines, decoders at every size, picture fits), 15 % of the suite's tests
# and about 85 % of its ASan time; the Release ctest runs them. MARKER_ASAN_ALL=1 runs them too
# (about 50 CPU-minutes).
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
# The suites that need only the lower libraries first: in one build ninja left driver_tests'
# largest batch (90 s) for the end, one core idle beside it.
small=()
for s in "${suites[@]}"; do [ "$s" != marker_tests ] && small+=("$s"); done
if ((${#small[@]})); then ninja -C "$build" -j"$(nproc)" "${small[@]}"; fi
ninja -C "$build" -j"$(nproc)" marker "${suites[@]}"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1 ${ASAN_OPTIONS:-}"
export LSAN_OPTIONS="suppressions=$root/tests/asan-suppressions.txt print_suppressions=0 ${LSAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1 ${UBSAN_OPTIONS:-}"
# The slow list as a negative gtest filter (comments and blank lines dropped).
slow_filter() {
  local pats
  pats=$(sed -e 's/#.*//' -e 's/[[:space:]]//g' "$root/tests/asan-slow-tests.txt" | grep -v '^$' | paste -sd: -)
  echo "*-$pats"
}

# The real-time tests (a producer and a drain against the device's clock: jobs, the stations'
# aborts and busy states, the kill mid-part) run alone after the shards: beside another ASan
# process on two cores the producer falls behind and the job underruns, which those tests fail on
# by design (JobSafety.StopFromAnotherThreadInRealTime…: 4 of 8 runs failed with two processes
# at once, 0 of 5 alone; ServeKill failed in CI the same way). The emulated board's command-line
# runs compare the wall clock with the board's own time, so they run alone too.
realtime='JobSafety.*:LmcEmulatedCli.*:ServeKill.*:JobEndToEnd.RealTimeMatchesVirtualTime'
realtime+=':StationTcp.AbortMidMark*:StationHttp.AbortMidMark*:StationHttp.TcpAndHttpClientsSeeTheSameStation'
realtime+=':StationModbus.StartWhileBusy*:StationModbus.MultipleCoilWriteActsInAddressOrder'
realtime+=':BoardIoStation.AnEdgeWhileMarking*:InterruptScope.*'

run_suite() {
  local suite=$1 f=$filter shards=${MARKER_ASAN_SHARDS:-2} status=0 t0 alone=
  t0=$(date +%s)
  if [ "$suite" = marker_tests ] && [ "$f" = "*" ]; then
    if [ -z "${MARKER_ASAN_ALL:-}" ]; then
      f=$(slow_filter)
      alone=$realtime-${f#\*-}  # the slow list stays out of the lone run too
      f=$f:$realtime
    else
      f="*-$realtime"
      alone=$realtime
    fi
  fi
  echo "asan: $suite ($shards shard(s))"
  local pids=() i
  for ((i = 0; i < shards; ++i)); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$build/tests/$suite" --gtest_brief=1 --gtest_filter="$f" \
      >"$build/asan-$suite-$i.log" 2>&1 &
    pids+=($!)
  done
  for ((i = 0; i < shards; ++i)); do
    if ! wait "${pids[$i]}"; then
      status=1
      echo "asan: $suite shard $i FAILED:" >&2
      tail -n 80 "$build/asan-$suite-$i.log" >&2
    fi
  done
  if [ -n "$alone" ]; then
    echo "asan: $suite $alone (alone)"
    if ! "$build/tests/$suite" --gtest_brief=1 --gtest_filter="$alone" >"$build/asan-$suite-alone.log" 2>&1; then
      status=1
      echo "asan: $suite $alone FAILED:" >&2
      tail -n 80 "$build/asan-$suite-alone.log" >&2
    fi
  fi
  echo "asan: $suite: $(( $(date +%s) - t0 )) s"
  return $status
}

status=0
for suite in "${suites[@]}"; do
  run_suite "$suite" || status=1
done
[ $status = 0 ] && echo "asan: clean"
exit $status
