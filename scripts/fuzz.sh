#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UBSan (in build-fuzz/, or
# $MARKER_FUZZ_BUILD) and runs each for SECONDS (default 15). Exits non-zero, naming the crashing
# input, if any target finds a crash, a sanitizer report, a leak, a broken invariant, an input
# slower than its -timeout or one that needs more memory than its -rss_limit_mb (a bomb).
#   scripts/fuzz.sh [SECONDS] [TARGET...]      (TARGET: a name below, e.g. png outline_font)
# Targets: the stroke-font loaders (jhf, lff, cxf), outline fonts (TrueType / CFF through
# FreeType), job files, data lists (CSV), the built-in font's glyph script, the PGM and PNG readers, code data (GS1,
# UDI, the zint wrapper), head profiles, the option-value parsers (numbers, "CX,CY,R", "WxH", --stock, --travel), the camera
# option (--camera KEY=VALUE,…), the station's HTTP requests (station_http: raw bytes to a server on
# loopback; modbus_request: raw Modbus TCP frames to a server on loopback; board_io_option: serve's --trigger
# and --signal), the per-part file names
# of mark --job --preview (part_file), and
# the LMC driver's readers (lmc_reply: replies and command words; cor_file: EzCad .cor files and
# captures). All 21 at the default 15 s run for about three minutes two at a time, plus the build
# (15 s, not 20: CI's whole run stays under 45 minutes with the ASan unit tests; the corpora
# persist between local runs, so a longer local run, e.g. fuzz.sh 300 png, goes deeper).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${MARKER_FUZZ_BUILD:-$root/build-fuzz}
all_targets=(jhf lff cxf outline_font job data_list glyph_script pgm png option_values camera_option plant_option lmc_reply cor_file code_data head_profile station_line station_http modbus_request board_io_option part_file)

seconds=15
if [[ ${1:-} =~ ^[0-9]+$ ]]; then
  seconds=$1
  shift
fi
targets=("${all_targets[@]}")
if (($#)); then
  targets=()
  for t in "$@"; do
    t=${t#fuzz_}
    if [[ " ${all_targets[*]} " != *" $t "* ]]; then
      echo "fuzz: unknown target '$t' (targets: ${all_targets[*]})" >&2
      exit 2
    fi
    targets+=("$t")
  done
fi

# -O1 with line tables only (asserts on): crash reports keep file:line, and a file compiles in
# well under the time of -O2 -g.
CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DMARKER_FUZZ=ON -DMARKER_TESTS=ON -DMARKER_BENCH=OFF >/dev/null
# Two jobs: the machine is shared (and has two cores).
ninja -C "$build" -j2 "${targets[@]/#/fuzz_}"

# Seeds: our fixtures, a few small real fonts, tests/fuzz/seeds/<target>/. The corpus directories
# persist between runs.
declare -A seeds=(
  [jhf]="$root/tests/fonts/data/*.jhf /usr/share/hershey-fonts/rowmans.jhf /usr/share/hershey-fonts/markers.jhf"
  [lff]="$root/tests/fonts/data/*.lff /usr/share/librecad/fonts/standard.lff /usr/share/librecad/fonts/greekp.lff"
  [cxf]="$root/tests/fonts/data/*.cxf"
  # Not the blob fonts: their 15 000-element glyph would make every run slow (cmap13.ttf has their map).
  [outline_font]="$(ls "$root"/tests/fonts/data/outline/*.[to]tf | grep -v '/blob_') $root/tests/fuzz/seeds/outline_font/*"
  [png]="$root/tests/fuzz/seeds/png/*.png"
  [glyph_script]="$root/tests/fuzz/seeds/glyph_script/*"
  [pgm]="$root/tests/fuzz/seeds/pgm/*"
  [option_values]="$root/tests/fuzz/seeds/option_values/*"
  [camera_option]="$root/tests/fuzz/seeds/camera_option/*"
  [plant_option]="$root/tests/fuzz/seeds/plant_option/*"
  [part_file]="$root/tests/fuzz/seeds/part_file/*"
  [job]="$root/tests/fuzz/job-seeds/*.json"
  [data_list]="$root/tests/fuzz/seeds/data_list/*"
  [code_data]="$root/tests/fuzz/code_data-seeds/*"
  [head_profile]="$root/tests/fuzz/head_profile-seeds/*.json"
  [station_line]="$root/tests/fuzz/seeds/station_line/*"
  [station_http]="$root/tests/fuzz/seeds/station_http/*"
  [modbus_request]="$root/tests/fuzz/seeds/modbus_request/*"
)
# Option values and replies are short; the others are files (a .cor table is ~68 kB).
# lmc_reply reaches a whole list packet (3072 bytes) for the masked link.
declare -A max_len=([option_values]=64 [camera_option]=256 [plant_option]=256 [glyph_script]=1024 [lmc_reply]=3200 [cor_file]=70000)
# The readers of hostile binary files get tighter limits than the default (10 s, 2048 MB), so an
# input that costs more than its size allows fails the run instead of slowing it: a PNG decodes at
# most its declared pixels (16 KB of input reach about 16 M pixels, 64 MB of floats), an outline
# font makes at most 64 glyphs within the per-glyph element limit.
declare -A timeout_s=([png]=5 [outline_font]=5)
declare -A rss_limit_mb=([png]=1024 [outline_font]=1024)

# Minimal valid inputs for the LMC readers, written into the corpus.
lmc_seeds() {
  local dir=$1
  # A status reply (READY | BUSY) and a GetSerialNo reply; a JumpTo and a MarkTo word.
  printf '\x00\x00\x00\x00\x00\x00\x24\x00' >"$dir/seed_reply_status"
  printf '\x00\x00\x01\x43\x4d\x4c\x20\x00' >"$dir/seed_reply_serial"
  printf '\x01\x80\x74\xd1\x8b\x2e\x00\x00\x31\x73\x00\x00\x05\x80\x74\xd1\xd1\x45\x00\x00\x46\x17\x00\x00' \
    >"$dir/seed_words"
  # Device and source names; a WritePort with the laser bit, a packet opening the oscillator.
  printf 'lmc-emulated:slowest' >"$dir/seed_device_emulated"
  printf 'lmc:4C4D4301' >"$dir/seed_device_serial"
  printf 'co2' >"$dir/seed_source"
  printf '\x21\x00\x01\x01\x00\x00\x00\x00\x00\x00\x00\x00' >"$dir/seed_write_port"
  { printf '\x51\x80\0\0\0\0\0\0\0\0\0\0\x21\x80\x01\0\0\0\0\0\0\0\0\0'; head -c $((3072 - 24)) /dev/zero; } \
    >"$dir/seed_packet"
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

# One target: its corpus and seeds, SECONDS of fuzzing, and a line of figures or the failure.
fuzz_target() {
  local target=$1
  local corpus="$build/fuzz-corpus/$target" artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  for seed in ${seeds[$target]:-}; do
    [ -f "$seed" ] && cp -n "$seed" "$corpus/" || true
  done
  [ "$target" = lmc_reply ] && lmc_seeds "$corpus"
  [ "$target" = cor_file ] && cor_seeds "$corpus"
  local dict=()
  [ -f "$root/tests/fuzz/$target.dict" ] && dict=(-dict="$root/tests/fuzz/$target.dict")
  echo "fuzz: $target for ${seconds}s"
  if ! "$build/tests/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -max_len="${max_len[$target]:-16384}" \
      -timeout="${timeout_s[$target]:-10}" -rss_limit_mb="${rss_limit_mb[$target]:-2048}" "${dict[@]}" \
      -artifact_prefix="$artifacts/" -print_final_stats=1 >"$build/fuzz-$target.log" 2>&1; then
    echo "fuzz: $target FAILED, see $build/fuzz-$target.log; inputs in $artifacts/" >&2
    tail -n 30 "$build/fuzz-$target.log" >&2
    return 1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$build/fuzz-$target.log" | sed "s/^/fuzz: $target /"
}

# Two targets at a time (MARKER_FUZZ_JOBS): each fuzzer is one process on one core, so every
# target still gets its SECONDS of a core, and the whole run takes half the time.
jobs=${MARKER_FUZZ_JOBS:-2}
status=0
running=0
for target in "${targets[@]}"; do
  if ((running >= jobs)); then
    wait -n || status=1
    running=$((running - 1))
  fi
  fuzz_target "$target" &
  running=$((running + 1))
done
while ((running > 0)); do
  wait -n || status=1
  running=$((running - 1))
done
exit $status
