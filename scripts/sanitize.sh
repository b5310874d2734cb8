#!/usr/bin/env bash
# Builds physdbg with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# into build-asan/, runs every test but the benchmarks under them, then runs
# each fuzz target for FUZZ_SECONDS (default 20) on its committed corpus.
# scripts/test.sh (the README's test command, and CI) ends with this.
# Leaks are reported except the third-party GL ones in tests/sanitizer/lsan.supp.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache hits across clones in other folders (CI builds a fresh clone): paths relative to here.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
bash scripts/setup.sh
CC=clang CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPHYSDBG_SANITIZE=ON \
  -DPHYSDBG_FUZZ=ON -DPHYSDBG_WITH_PEERS=OFF >/dev/null
targets=(physdbg engine_tests peer_tests stability_tests report_tests render_tests golden_tests gpu_tests
         fuzz_scene_loader fuzz_hull_contact fuzz_recording fuzz_png_compare)
cmake --build build-asan -j "$(nproc)" --target "${targets[@]}"

source scripts/sanitizer_env.sh
export LP_NUM_THREADS=1
# EGL unloads Mesa's DRI driver on eglTerminate, after which LeakSanitizer can
# no longer name the library of the driver's own 112-byte leak, and the
# suppression cannot match it. Preloading keeps the driver mapped until exit.
driver=/usr/lib/x86_64-linux-gnu/dri/swrast_dri.so
preload=()
[ -f "$driver" ] && preload=(env LD_PRELOAD="$driver")
start=$(date +%s)
# Left out here, run by the release build: long runs of code that shorter
# tests walk too (a 5050-box pyramid twice, 1000-step stacks, 512-body piles
# on 1, 2 and 4 threads, 100,000-point hulls, every built-in scene twice for
# the broad-phase variants and the GPU broad phase, thread-count sweeps of
# wide pyramids; the shorter determinism tests still run the parallel code
# here). Under the sanitizers they cost about 40% of this stage and find
# nothing the short ones would not.
long_runs='NOT_BUILT|TwoRunsOfThePyramidAreBitIdentical|Seeds/MixedPile|ThreadDeterminism\.MixedPile'
long_runs+='|HundredThousandPoints|StabilityStacking\.(SmallTimeStep|LargePyramid)|PyramidWithABaseOf20StandsFor1000Steps'
long_runs+='|BroadPhaseVariantsGiveBitIdenticalMotion|GpuWorld\..*BitForBitWithTheGpuBroadPhase'
long_runs+='|WideContactSolve\.(AnyThreadCountGivesTheSameStates|ScalarSolveIsThreadIndependentToo)'
long_runs+='|ThreadDeterminism\.WidePyramid|StackPenetrationDoesNotGrowWithSubsteps'
"${preload[@]}" ctest --test-dir build-asan --output-on-failure -j "$(nproc)" -LE bench -E "$long_runs"
echo "sanitize: tests under ASan+UBSan took $(( $(date +%s) - start )) s"
bash scripts/fuzz.sh --build-dir build-asan "${FUZZ_SECONDS:-20}"
