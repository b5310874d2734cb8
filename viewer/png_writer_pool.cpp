#include "viewer/png_writer_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>


namespace physdbg::viewer {

PoolSize framePoolSize(int width, int height) {
  constexpr std::size_t maxQueuedBytes = std::size_t{1} << 30;
  const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
  const std::size_t frameBytes = std::max<std::size_t>(1, std::size_t(width) * std::size_t(height) * 4);
  return {static_cast<int>(cores - 1), std::clamp<std::size_t>(maxQueuedBytes / frameBytes, 1, 2 * cores)};
}

PngWriterPool::PngWriterPool(PoolSize size, std::string option)
    : maxQueued_(size.maxQueued), option_(std::move(option)) {
  for (int i = 0; i < size.workers; ++i) workers_.emplace_back([this] { work(); });
}

PngWriterPool::~PngWriterPool() {
  {
    std::unique_lock lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  workers_.clear();  // joins
}

void PngWriterPool::submit(std::string path, render::Image image) {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < maxQueued_ || failure_; });
  if (failure_) rethrowFailure();
  queue_.push_back({std::move(path), std::move(image)});
  changed_.notify_all();
}

void PngWriterPool::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || failure_; });
  if (failure_) rethrowFailure();
}

double PngWriterPool::encodeSeconds() const {
  std::scoped_lock lock(mutex_);
  return encodeSeconds_;
}

void PngWriterPool::rethrowFailure() {
  std::exception_ptr failure = failure_;
  std::rethrow_exception(failure);
}

void PngWriterPool::work() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
      if (queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      ++busy_;
    }
    changed_.notify_all();
    const auto start = std::chrono::steady_clock::now();
    std::exception_ptr failure;
    try {
      render::writePng(job.path, job.image);
    } catch (const std::runtime_error& error) {
      failure = std::make_exception_ptr(std::invalid_argument(option_ + ": " + error.what()));
    } catch (...) {
      failure = std::current_exception();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    {
      std::scoped_lock lock(mutex_);
      --busy_;
      encodeSeconds_ += seconds;
      if (failure && !failure_) failure_ = failure;
    }
    changed_.notify_all();
  }
}

}  // namespace physdbg::viewer
