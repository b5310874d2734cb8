#pragma once
// How much parallel speed the host gives right now: a fixed arithmetic chain
// run on one thread, then on `threads` threads at once, as threads x the
// one-thread time over the all-thread time (2 on two free cores, near 1 when
// a shared machine's second core is busy elsewhere). The scene benchmarks
// record it beside each all-core row, because on shared machines the
// all-core ratio says as much about the host as about the engine.
namespace physdbg::bench {

double measureHostScaling(int threads);

}  // namespace physdbg::bench
