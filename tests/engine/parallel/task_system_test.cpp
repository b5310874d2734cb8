#include "engine/parallel/task_system.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace physdbg {
namespace {

// Every index is visited exactly once, for any thread count and grain.
TEST(TaskSystem, VisitsEveryIndexOnce) {
  for (const int threads : {1, 2, 4}) {
    const TaskSystem tasks(threads);
    EXPECT_EQ(tasks.threadCount(), threads);
    for (const std::size_t grain : {1u, 7u, 64u, 5000u}) {
      std::vector<int> visits(1000, 0);
      tasks.parallelFor(visits.size(), grain, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) ++visits[i];
      });
      for (std::size_t i = 0; i < visits.size(); ++i) ASSERT_EQ(visits[i], 1) << "threads " << threads << " grain " << grain;
    }
  }
}

TEST(TaskSystem, OneThreadRunsInlineInOrder) {
  const TaskSystem tasks(1);
  const std::thread::id caller = std::this_thread::get_id();
  int calls = 0;
  tasks.parallelFor(100, 1, [&](std::size_t begin, std::size_t end) {
    EXPECT_EQ(std::this_thread::get_id(), caller);
    EXPECT_EQ(begin, 0u);
    EXPECT_EQ(end, 100u);
    ++calls;
  });
  EXPECT_EQ(calls, 1);
}

// Each piece waits until `threads` pieces run at once (or 20 s pass, on a
// machine too loaded to schedule them): proof that that many threads work
// together, with no timing assumption beyond the generous timeout.
int mostAtOnce(const TaskSystem& tasks, int threads) {
  std::atomic<int> running{0}, most{0};
  tasks.parallelFor(static_cast<std::size_t>(threads) * 4, 1, [&](std::size_t, std::size_t) {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (most.load() < threads && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    --running;
  });
  return most.load();
}

TEST(TaskSystem, UsesMoreThanOneThreadWhenAsked) {
  const TaskSystem tasks(2);
  EXPECT_EQ(mostAtOnce(tasks, 2), 2);
}

// More threads than cores really run (a determinism test asks for 4 on 2).
TEST(TaskSystem, MoreThreadsThanCoresAllRun) {
  const int threads = TaskSystem::hardwareThreads() + 2;
  const TaskSystem tasks(threads);
  EXPECT_EQ(mostAtOnce(tasks, threads), threads);
}

TEST(TaskSystem, ZeroThreadsMeansTheMachines) {
  EXPECT_EQ(TaskSystem(0).threadCount(), TaskSystem::hardwareThreads());
}

TEST(TaskSystem, ExceptionsReachTheCaller) {
  const TaskSystem tasks(2);
  EXPECT_THROW(tasks.parallelFor(100, 1, [](std::size_t begin, std::size_t) {
    if (begin >= 50) throw std::runtime_error("piece failed");
  }), std::runtime_error);
}

}  // namespace
}  // namespace physdbg
