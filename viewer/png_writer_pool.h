#pragma once
// Encodes PNG frames on worker threads while the main thread simulates and
// draws the next frame: PNG encoding, not drawing, is the bottleneck of a
// debug video (see shared NOTES). The queue is bounded so memory stays flat.
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/image.h"

namespace physdbg::viewer {

struct PoolSize {
  int workers = 1;
  std::size_t maxQueued = 2;
};

// One worker per core but one (the drawing thread keeps one), and a queue of
// two frames per core, shortened for large frames so that queued images
// stay under 1 GiB.
PoolSize framePoolSize(int width, int height);

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

  double encodeSeconds() const;  // summed over workers

 private:
  struct Job {
    std::string path;
    render::Image image;
  };
  void work();
  void rethrowFailure();

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Job> queue_;
  std::size_t maxQueued_;
  std::string option_;
  int busy_ = 0;
  bool stopping_ = false;
  std::exception_ptr failure_;
  double encodeSeconds_ = 0;
  std::vector<std::jthread> workers_;
};

}  // namespace physdbg::viewer
