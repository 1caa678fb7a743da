#!/usr/bin/env bash
# The whole test suite: sets up, builds, runs every GoogleTest suite through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh all
ctest --test-dir build --output-on-failure -j2 "$@"
