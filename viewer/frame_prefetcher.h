#pragma once
// Produces frames first..last-1 on a thread of its own, a bounded number
// ahead of the consumer: the next frame's physics runs while the current one
// draws. Only the producing thread touches what `produce` captures until the
// last frame has been taken (next() returned nothing), so the consumer may
// read it then. Destroying the prefetcher early (the consumer failed) stops
// the producer after the frame it is working on; nothing waits forever.
#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <thread>

#include "viewer/bounded_queue.h"

namespace physdbg::viewer {

template <typename Item>
class FramePrefetcher {
 public:
  FramePrefetcher(int first, int last, std::size_t ahead, std::function<Item(int)> produce)
      : queue_(ahead), thread_([this, first, last, produce = std::move(produce)] { run(first, last, produce); }) {}
  ~FramePrefetcher() { queue_.close(); }  // then thread_, destroyed first, joins
  FramePrefetcher(const FramePrefetcher&) = delete;
  FramePrefetcher& operator=(const FramePrefetcher&) = delete;

  // The next frame in order; nothing after the last. Rethrows what `produce`
  // threw, after the frames it produced before.
  std::optional<Item> next() {
    std::optional<Item> item = queue_.pop();
    if (item) return item;
    if (thread_.joinable()) thread_.join();  // orders the producer's writes before ours
    if (failure_) std::rethrow_exception(failure_);
    return std::nullopt;
  }

 private:
  void run(int first, int last, const std::function<Item(int)>& produce) {
    try {
      for (int index = first; index < last; ++index)
        if (!queue_.push(produce(index))) break;
    } catch (...) {
      failure_ = std::current_exception();
    }
    queue_.close();
  }

  BoundedQueue<Item> queue_;
  std::exception_ptr failure_;  // written by the producer, read after joining it
  std::jthread thread_;         // last: starts once the queue exists, joins before it dies
};

}  // namespace physdbg::viewer
