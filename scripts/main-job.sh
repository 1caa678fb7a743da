#!/usr/bin/env bash
# The main job: sets up and builds if needed, then marks a serial number with the built-in font
# on the simulated scanner (SL10 head, blanking corners, real time at 100 kHz), prints its figures
# and writes the preview picture serial.png (dose under the planned path).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh marker >/dev/null
build/marker/marker mark "SN 2026-000123" --height 4 --align center --preview serial.png "$@"
