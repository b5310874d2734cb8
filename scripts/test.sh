#!/usr/bin/env bash
# Sets up, builds and runs every test, then the same tests under AddressSanitizer and
# UndefinedBehaviorSanitizer with a short fuzzing run (scripts/sanitize.sh).
# This is the README's test command and what CI runs. PHYSDBG_SKIP_SANITIZE=1 skips
# the sanitizer stage for a quick local run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
export LP_NUM_THREADS=1
ctest --test-dir build --output-on-failure -j "$(nproc)"
if [ "${PHYSDBG_SKIP_SANITIZE:-0}" != 1 ]; then bash scripts/sanitize.sh; fi
