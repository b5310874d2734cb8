#!/usr/bin/env bash
# Sets up, builds and renders the default scene to out/default/ (PNG frames),
# plus out/default.mp4 when ffmpeg is installed. This is the README's first command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
export LP_NUM_THREADS="${LP_NUM_THREADS:-1}"
video=()
if command -v ffmpeg >/dev/null 2>&1; then video=(--video out/default.mp4); fi
build/cli/physdbg render default -o out/default "${video[@]}"
