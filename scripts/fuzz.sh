#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UBSan (in build-fuzz/, or
# $MARKER_FUZZ_BUILD) and runs each for SECONDS (default 20). Exits non-zero, naming the crashing
# input, if any target finds a crash, a sanitizer report, a leak or a broken invariant.
#   scripts/fuzz.sh [SECONDS]
# Targets: the font loaders (jhf, lff, cxf), job files, the built-in font's glyph script, the PGM
# reader of tool-measure and the option-value parsers (numbers, "CX,CY,R", "WxH").
set -euo pipefail

seconds=${1:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}
targets=(jhf lff cxf job glyph_script pgm option_values)

CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMARKER_FUZZ=ON -DMARKER_TESTS=ON -DMARKER_BENCH=OFF >/dev/null
ninja -C "$build" "${targets[@]/#/fuzz_}"

# Seeds: our fixtures, a few small real fonts, tests/fuzz/seeds/<target>/. The corpus directories
# persist between runs.
declare -A seeds=(
  [jhf]="$root/tests/fonts/data/*.jhf /usr/share/hershey-fonts/rowmans.jhf /usr/share/hershey-fonts/markers.jhf"
  [lff]="$root/tests/fonts/data/*.lff /usr/share/librecad/fonts/standard.lff /usr/share/librecad/fonts/greekp.lff"
  [cxf]="$root/tests/fonts/data/*.cxf"
  [glyph_script]="$root/tests/fuzz/seeds/glyph_script/*"
  [pgm]="$root/tests/fuzz/seeds/pgm/*"
  [option_values]="$root/tests/fuzz/seeds/option_values/*"
  [job]="$root/tests/fuzz/job-seeds/*.json"
)
# Option values are short; the others are files.
declare -A max_len=([option_values]=64 [glyph_script]=1024)

status=0
for target in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  for seed in ${seeds[$target]}; do
    [ -f "$seed" ] && cp -n "$seed" "$corpus/" || true
  done
  echo "fuzz: $target for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -max_len="${max_len[$target]:-16384}" \
      -timeout=10 -rss_limit_mb=2048 -dict="$root/tests/fuzz/$target.dict" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$build/fuzz-$target.log" 2>&1; then
    echo "fuzz: $target FAILED, see $build/fuzz-$target.log; inputs in $artifacts/" >&2
    tail -n 30 "$build/fuzz-$target.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$target.log" | sed "s/^/fuzz: $target /"
  fi
done
exit $status
