#include "engine/parallel/task_system.h"

#include <gtest/gtest.h>

#include <atomic>
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

TEST(TaskSystem, UsesMoreThanOneThreadWhenAsked) {
  const TaskSystem tasks(2);
  std::atomic<int> running{0}, most{0};
  tasks.parallelFor(64, 1, [&](std::size_t, std::size_t) {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    --running;
  });
  EXPECT_EQ(most.load(), 2);
}

// More threads than cores really run (a determinism test asks for 4 on 2).
TEST(TaskSystem, MoreThreadsThanCoresAllRun) {
  const int threads = TaskSystem::hardwareThreads() + 2;
  const TaskSystem tasks(threads);
  std::atomic<int> running{0}, most{0};
  tasks.parallelFor(256, 1, [&](std::size_t, std::size_t) {
    const int now = ++running;
    int seen = most.load();
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    --running;
  });
  EXPECT_EQ(most.load(), threads);
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
