#pragma once
// Work spread over a fixed number of threads (oneTBB underneath, kept out of
// this header so the engine's widely included headers stay light).
//
// Determinism: a loop's result must not depend on how its range is split or
// which thread runs a piece. parallelFor hands out disjoint index ranges;
// callers write only to slots owned by their indices and combine partial
// results afterwards in index order. With one thread nothing is spawned: the
// body runs inline, in order, on the calling thread.
#include <cstddef>
#include <functional>
#include <memory>

namespace physdbg {

class TaskSystem {
 public:
  // threads <= 0: one per hardware thread (std::thread::hardware_concurrency).
  explicit TaskSystem(int threads = 1);
  ~TaskSystem();
  TaskSystem(const TaskSystem&) = delete;
  TaskSystem& operator=(const TaskSystem&) = delete;

  int threadCount() const { return threads_; }

  // body(begin, end) over [0, count) in pieces of at most `grain` indices
  // (halves of halves, so more than grain / 2 each); a count up to grain runs
  // inline on the caller's thread. Returns when every piece has run.
  // Exceptions from a body propagate.
  void parallelFor(std::size_t count, std::size_t grain,
                   const std::function<void(std::size_t begin, std::size_t end)>& body) const;

  // The count the machine offers, at least 1.
  static int hardwareThreads();

 private:
  struct Arena;
  int threads_ = 1;
  std::unique_ptr<Arena> arena_;  // null with one thread
};

}  // namespace physdbg
