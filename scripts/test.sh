#!/usr/bin/env bash
# Sets up, builds and runs every test. This is the README's test command and what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
export LP_NUM_THREADS=1
ctest --test-dir build --output-on-failure -j "$(nproc)"
