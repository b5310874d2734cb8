#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each (default 60) on its committed
# seed corpus (fuzz/corpus/TARGET), keeping new inputs in BUILD/fuzz-work/ and
# any crash in BUILD/fuzz-findings/. Prints executions per target; exits 1 on a finding.
# Usage: bash scripts/fuzz.sh [--build-dir DIR] [SECONDS] [TARGET...]
# Without --build-dir it builds build-fuzz/ with clang + ASan + UBSan first.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache hits across clones in other folders (CI builds a fresh clone): paths relative to here.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
build=""
if [ "${1:-}" = "--build-dir" ]; then build="$2"; shift 2; fi
seconds="${1:-60}"
shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_scene_loader fuzz_hull_contact fuzz_recording fuzz_png_compare)
if [ -z "$build" ]; then
  build=build-fuzz
  bash scripts/setup.sh
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHYSDBG_SANITIZE=ON \
    -DPHYSDBG_FUZZ=ON -DPHYSDBG_WITH_PEERS=OFF -DPHYSDBG_BUILD_TESTS=OFF >/dev/null
  cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
fi
source scripts/sanitizer_env.sh
findings=0
for target in "${targets[@]}"; do
  work="$build/fuzz-work/$target"
  artifacts="$build/fuzz-findings"
  mkdir -p "$work" "$artifacts"
  options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1
           -artifact_prefix="$artifacts/$target-")
  [ -f "fuzz/$target.dict" ] && options+=(-dict="fuzz/$target.dict")
  log="$build/fuzz-work/$target.log"
  if "$build/fuzz/$target" "${options[@]}" "$work" "fuzz/corpus/$target" >"$log" 2>&1; then status=ok
  else status=FOUND; findings=1; fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz: $target: $status, $runs executions in ${seconds} s (corpus $(ls "$work" | wc -l) new inputs)"
  if [ "$status" != ok ]; then tail -40 "$log"; fi
done
exit "$findings"
