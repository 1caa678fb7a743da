#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UBSan (in build-fuzz/, or
# $MARKER_FUZZ_BUILD) and runs each for SECONDS (default 20). Exits non-zero, naming the crashing
# input, if any target finds a crash, a sanitizer report, a leak or a broken invariant.
#   scripts/fuzz.sh [SECONDS]
# Targets: the font loaders (jhf, lff, cxf), job files, data lists (CSV), the built-in font's glyph script, the PGM
# reader, code data (GS1, UDI, the zint wrapper), head profiles, the option-value parsers (numbers, "CX,CY,R", "WxH"), and the LMC
# driver's readers (lmc_reply: replies and command words; cor_file: EzCad .cor files and captures).
set -euo pipefail

seconds=${1:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}
targets=(jhf lff cxf job data_list glyph_script pgm option_values lmc_reply cor_file code_data head_profile)

# -O1 with line tables only (asserts on): crash reports keep file:line, and a file compiles in
# well under the time of -O2 -g.
CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
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
  [data_list]="$root/tests/fuzz/seeds/data_list/*"
  [code_data]="$root/tests/fuzz/code_data-seeds/*"
  [head_profile]="$root/tests/fuzz/head_profile-seeds/*.json"
)
# Option values and replies are short; the others are files (a .cor table is ~68 kB).
declare -A max_len=([option_values]=64 [glyph_script]=1024 [lmc_reply]=256 [cor_file]=70000)

# Minimal valid inputs for the LMC readers, written into the corpus.
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
for target in "${targets[@]}"; do
  corpus="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  for seed in ${seeds[$target]:-}; do
    [ -f "$seed" ] && cp -n "$seed" "$corpus/" || true
  done
  [ "$target" = lmc_reply ] && lmc_seeds "$corpus"
  [ "$target" = cor_file ] && cor_seeds "$corpus"
  dict=()
  [ -f "$root/tests/fuzz/$target.dict" ] && dict=(-dict="$root/tests/fuzz/$target.dict")
  echo "fuzz: $target for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -max_len="${max_len[$target]:-16384}" \
      -timeout=10 -rss_limit_mb=2048 "${dict[@]}" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$build/fuzz-$target.log" 2>&1; then
    echo "fuzz: $target FAILED, see $build/fuzz-$target.log; inputs in $artifacts/" >&2
    tail -n 30 "$build/fuzz-$target.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$target.log" | sed "s/^/fuzz: $target /"
  fi
done
exit $status
