#!/usr/bin/env bash
# The main job: builds if needed, then lays out a serial number with the built-in font and
# writes a preview picture (serial.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh marker >/dev/null
serial="SN 2026-000123"
build/marker/marker layout "$serial" --height 4 --align center
build/marker/marker preview "$serial" --height 4 --align center -o serial.png
