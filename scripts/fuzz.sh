#!/usr/bin/env bash
# Builds the parser fuzz targets (font loaders, job files, head profiles) with clang, AddressSanitizer
# and UBSan (in build-fuzz/, or
# $MARKER_FUZZ_BUILD) and runs each for SECONDS (default 20). Exits non-zero, naming the crashing
# input, if any target finds a crash, a sanitizer report, a leak or a broken invariant.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail

seconds=${1:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}

CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMARKER_FUZZ=ON -DMARKER_TESTS=ON -DMARKER_BENCH=OFF >/dev/null
ninja -C "$build" fuzz_jhf fuzz_lff fuzz_cxf fuzz_job fuzz_head_profile

# Seeds: our fixtures and a few small real fonts. The corpus directories persist between runs.
declare -A seeds=(
  [jhf]="$root/tests/fonts/data/*.jhf /usr/share/hershey-fonts/rowmans.jhf /usr/share/hershey-fonts/markers.jhf"
  [lff]="$root/tests/fonts/data/*.lff /usr/share/librecad/fonts/standard.lff /usr/share/librecad/fonts/greekp.lff"
  [cxf]="$root/tests/fonts/data/*.cxf"
  [job]="$root/tests/fuzz/job-seeds/*.json"
  [head_profile]="$root/tests/fuzz/head_profile-seeds/*.json"
)

status=0
for format in jhf lff cxf job head_profile; do
  corpus="$build/fuzz-corpus/$format"
  artifacts="$build/fuzz-artifacts/$format"
  mkdir -p "$corpus" "$artifacts"
  for seed in ${seeds[$format]}; do
    [ -f "$seed" ] && cp -n "$seed" "$corpus/" || true
  done
  echo "fuzz: $format for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$format" "$corpus" -max_total_time="$seconds" -max_len=16384 \
      -timeout=10 -rss_limit_mb=2048 -dict="$root/tests/fuzz/$format.dict" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$build/fuzz-$format.log" 2>&1; then
    echo "fuzz: $format FAILED, see $build/fuzz-$format.log; inputs in $artifacts/" >&2
    tail -n 30 "$build/fuzz-$format.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$format.log" | sed "s/^/fuzz: $format /"
  fi
done
exit $status
