#pragma once
// Encodes PNG frames on worker threads while the main thread draws the next
// frame: PNG encoding is as slow as drawing a debug frame (see shared NOTES).
// Frames are encoded in parallel but their files are written in the order
// they were submitted, so after a failure (a full disk, a missing folder)
// every frame before the failed one is on disk and none after it. The queue
// is bounded so memory stays flat.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/image.h"

namespace physdbg::viewer {

struct PoolSize {
  int workers = 1;  // 0: submit() encodes and writes on the caller's thread
  std::size_t maxQueued = 2;
};

// One worker per core but one (the drawing thread keeps one), and a queue of
// two frames per core, shortened for large frames so that queued images
// stay under 1 GiB.
PoolSize framePoolSize(int width, int height);

// Seconds summed over the workers, and how long submit() waited for room:
// a drawing thread that waits here is bound by encoding.
struct PoolTimes {
  double encodeSeconds = 0, writeSeconds = 0, submitWaitSeconds = 0;
};

class PngWriterPool {
 public:
  // A frame that cannot be written fails the run as a std::invalid_argument
  // naming `option` (the output folder's option) and the file; cli/ reports
  // it as a usage error.
  PngWriterPool(PoolSize size, std::string option);
  ~PngWriterPool();  // waits for queued frames
  PngWriterPool(const PngWriterPool&) = delete;
  PngWriterPool& operator=(const PngWriterPool&) = delete;

  // Blocks while the queue is full. Rethrows a worker's failure.
  void submit(std::string path, render::Image image);
  // Waits until every submitted frame is written; rethrows a worker's failure.
  void finish();

  PoolTimes times() const;
  double encodeSeconds() const { return times().encodeSeconds; }

 private:
  struct Job {
    std::uint64_t sequence = 0;
    std::string path;
    render::Image image;
  };
  struct Encoded {
    std::string path;
    std::vector<std::uint8_t> bytes;
    std::exception_ptr failure;
  };
  void work();
  Encoded encode(Job& job);
  void writeInOrder(std::unique_lock<std::mutex>& lock);
  std::exception_ptr write(const Encoded& frame);
  void rethrowFailure();

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::map<std::uint64_t, Encoded> encoded_;  // waiting for the frames before them
  std::uint64_t submitted_ = 0, written_ = 0;
  bool writing_ = false;  // one thread writes at a time, in sequence
  std::size_t maxQueued_;
  std::string option_;
  bool stopping_ = false;
  std::exception_ptr failure_;
  PoolTimes times_;
  std::vector<std::jthread> workers_;  // last: joined before the state above dies
};

}  // namespace physdbg::viewer
