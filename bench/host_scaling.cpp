#include "bench/host_scaling.h"

#include <chrono>
#include <thread>
#include <vector>

namespace physdbg::bench {
namespace {

// About 30 ms of dependent multiply-adds on one core (20M steps); nothing shared, no
// memory traffic, so only the cores' availability sets its speed.
double arithmeticChain() {
  volatile double seed = 1.0;
  double x = seed;
  for (int i = 0; i < 20'000'000; ++i) x = x * 0.999999 + 1e-7;
  return x;
}

template <typename Work>
double secondsOf(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double measureHostScaling(int threads) {
  if (threads <= 1) return 1.0;
  volatile double sink = 0.0;
  const double single = secondsOf([&] { sink = sink + arithmeticChain(); });
  const double all = secondsOf([&] {
    std::vector<std::jthread> workers;
    std::vector<double> results(threads, 0.0);
    for (int t = 0; t < threads; ++t) workers.emplace_back([&results, t] { results[t] = arithmeticChain(); });
    workers.clear();  // joins
    for (double r : results) sink = sink + r;
  });
  return all > 0.0 ? threads * single / all : 0.0;
}

}  // namespace physdbg::bench
