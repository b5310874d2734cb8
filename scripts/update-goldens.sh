#!/usr/bin/env bash
# Regenerates the golden images in tests/golden/KEY/ (KEY names this machine's
# Mesa version and GL renderer) after an intended change to the engine, the
# scenes or the renderer, then runs the golden tests. Review the new PNGs
# (git diff --stat tests/golden; physdbg compare OLD NEW --diff D.png) before
# committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
export LP_NUM_THREADS=1
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j 2 --target golden_update golden_tests
build/tests/golden_update tests/golden
ctest --test-dir build -L golden --output-on-failure
