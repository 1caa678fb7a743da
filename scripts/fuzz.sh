#!/usr/bin/env bash
# Builds the fuzz targets with clang, AddressSanitizer and UBSan (in build-fuzz/, or
# $MARKER_FUZZ_BUILD) and runs each for SECONDS (default 20): the font loaders (jhf, lff, cxf)
# and the LMC driver's readers (lmc_reply: replies and command words; cor_file: EzCad .cor files
# and capture files). Exits non-zero, naming the crashing input, if any target finds a crash, a
# sanitizer report, a leak or a broken invariant.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail

seconds=${1:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}
targets=(jhf lff cxf lmc_reply cor_file)

CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMARKER_FUZZ=ON -DMARKER_TESTS=ON -DMARKER_BENCH=OFF >/dev/null
ninja -C "$build" "${targets[@]/#/fuzz_}"

# Seeds: our fixtures and a few small real fonts; for the LMC readers, minimal valid inputs
# written below. The corpus directories persist between runs.
declare -A seeds=(
  [jhf]="$root/tests/fonts/data/*.jhf /usr/share/hershey-fonts/rowmans.jhf /usr/share/hershey-fonts/markers.jhf"
  [lff]="$root/tests/fonts/data/*.lff /usr/share/librecad/fonts/standard.lff /usr/share/librecad/fonts/greekp.lff"
  [cxf]="$root/tests/fonts/data/*.cxf"
  [lmc_reply]=""
  [cor_file]=""
)
declare -A max_len=([jhf]=16384 [lff]=16384 [cxf]=16384 [lmc_reply]=256 [cor_file]=70000)

lmc_seeds() {
  local dir=$1
  # A status reply (READY | BUSY) and a GetSerialNo reply; a JumpTo and a MarkTo word.
  printf '\x00\x00\x00\x00\x00\x00\x24\x00' >"$dir/seed_reply_status"
  printf '\x00\x00\x01\x43\x4d\x4c\x20\x00' >"$dir/seed_reply_serial"
  printf '\x01\x80\x74\xd1\x8b\x2e\x00\x00\x31\x73\x00\x00\x05\x80\x74\xd1\xd1\x45\x00\x00\x46\x17\x00\x00' \
    >"$dir/seed_words"
}
cor_seeds() {
  local dir=$1
  # A legacy (int32) table and an LMC1COR_1.0 (float64) table, all deltas 0; two captures.
  head -c $((0x24 + 4225 * 8)) /dev/zero >"$dir/seed_legacy.cor"
  { printf 'L\0M\0C\0001\0C\0O\0R\0_\0001\0.\0000\0'; head -c $((0x210 - 22 + 4225 * 16)) /dev/zero; } \
    >"$dir/seed_lmc1cor.cor"
  { printf 'S\x07\0\0\0\0\0\0\0\0\0\0\0L'; head -c 3072 /dev/zero; } >"$dir/seed_capture.lmc"
  printf 'S\x12\0\0\0\0\0\0\0\0\0\0\0' >"$dir/seed_capture_single.lmc"
}

status=0
for format in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$format"
  artifacts="$build/fuzz-artifacts/$format"
  mkdir -p "$corpus" "$artifacts"
  for seed in ${seeds[$format]}; do
    [ -f "$seed" ] && cp -n "$seed" "$corpus/" || true
  done
  [ "$format" = lmc_reply ] && lmc_seeds "$corpus"
  [ "$format" = cor_file ] && cor_seeds "$corpus"
  dict=()
  [ -f "$root/tests/fuzz/$format.dict" ] && dict=(-dict="$root/tests/fuzz/$format.dict")
  echo "fuzz: $format for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$format" "$corpus" -max_total_time="$seconds" -max_len="${max_len[$format]}" \
      -timeout=10 -rss_limit_mb=2048 "${dict[@]}" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$build/fuzz-$format.log" 2>&1; then
    echo "fuzz: $format FAILED, see $build/fuzz-$format.log; inputs in $artifacts/" >&2
    tail -n 30 "$build/fuzz-$format.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$format.log" | sed "s/^/fuzz: $format /"
  fi
done
exit $status
