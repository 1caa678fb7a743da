#!/usr/bin/env bash
# Installs what the build needs (quietly when it is there) and builds into ./build: the targets
# given, or without any everything, the benchmarks too (scripts/test.sh builds `all`, which
# leaves the benchmarks out).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
if (($# == 0)); then
  set -- all benchmarks
fi
ninja -C build "$@"
