#include "engine/parallel/task_system.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <thread>

namespace physdbg {

// An arena caps the threads a world uses, whatever else the process runs.
// Asked for more threads than the machine has (a determinism test running 4
// on 2 cores), oneTBB would quietly keep its default worker count and print a
// warning; the control raises that limit while this arena lives. oneTBB obeys
// the smallest limit alive, so every arena sets the same one, the most
// threads a world may ask for: a 4-thread arena beside a 2-thread one still
// gets its 4. Workers are only made as arenas ask for them.
constexpr std::size_t mostThreads = 256;  // the range of --threads and the scene key

struct TaskSystem::Arena {
  explicit Arena(int threads)
      : limit(tbb::global_control::max_allowed_parallelism,
              std::max(mostThreads, static_cast<std::size_t>(std::max(threads, TaskSystem::hardwareThreads())))),
        arena(threads) {}
  tbb::global_control limit;
  tbb::task_arena arena;
};

int TaskSystem::hardwareThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

TaskSystem::TaskSystem(int threads) : threads_(threads <= 0 ? hardwareThreads() : threads) {
  if (threads_ > 1) arena_ = std::make_unique<Arena>(threads_);
}

TaskSystem::~TaskSystem() = default;

void TaskSystem::parallelFor(std::size_t count, std::size_t grain,
                             const std::function<void(std::size_t, std::size_t)>& body) const {
  if (count == 0) return;
  grain = std::max<std::size_t>(grain, 1);
  if (!arena_ || count <= grain) {
    body(0, count);
    return;
  }
  arena_->arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, count, grain),
        [&](const tbb::blocked_range<std::size_t>& range) { body(range.begin(), range.end()); },
        tbb::simple_partitioner());
  });
}

}  // namespace physdbg
