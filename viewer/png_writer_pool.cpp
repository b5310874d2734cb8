#include "viewer/png_writer_pool.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace physdbg::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

}  // namespace

PoolSize framePoolSize(int width, int height) {
  constexpr std::size_t maxQueuedBytes = std::size_t{1} << 30;
  const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
  const std::size_t frameBytes = std::max<std::size_t>(1, std::size_t(width) * std::size_t(height) * 4);
  return {static_cast<int>(cores - 1), std::clamp<std::size_t>(maxQueuedBytes / frameBytes, 1, 2 * cores)};
}

PngWriterPool::PngWriterPool(PoolSize size, std::string option)
    : maxQueued_(std::max<std::size_t>(1, size.maxQueued)), option_(std::move(option)) {
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
  const auto start = Clock::now();
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < maxQueued_ || failure_; });
  times_.submitWaitSeconds += secondsSince(start);
  if (failure_) rethrowFailure();
  Job job{submitted_++, std::move(path), std::move(image)};
  if (workers_.empty()) {  // serial: encode and write here
    lock.unlock();
    Encoded frame = encode(job);
    lock.lock();
    encoded_.emplace(job.sequence, std::move(frame));
    writeInOrder(lock);
    if (failure_) rethrowFailure();
    return;
  }
  queue_.push_back(std::move(job));
  changed_.notify_all();
}

void PngWriterPool::finish() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return written_ == submitted_ || failure_; });
  if (failure_) rethrowFailure();
}

PoolTimes PngWriterPool::times() const {
  std::scoped_lock lock(mutex_);
  return times_;
}

void PngWriterPool::rethrowFailure() {
  std::exception_ptr failure = failure_;
  std::rethrow_exception(failure);
}

// Called without the lock.
PngWriterPool::Encoded PngWriterPool::encode(Job& job) {
  const auto start = Clock::now();
  Encoded frame{std::move(job.path), {}, nullptr};
  try {
    frame.bytes = render::encodePng(job.image);
  } catch (...) {
    frame.failure = std::current_exception();
  }
  job.image = {};  // its 3.7 MB go back before the next frame's
  const double seconds = secondsSince(start);
  std::scoped_lock lock(mutex_);
  times_.encodeSeconds += seconds;
  return frame;
}

// Called without the lock.
std::exception_ptr PngWriterPool::write(const Encoded& frame) {
  if (frame.failure) return frame.failure;
  try {
    render::writePngBytes(frame.path, frame.bytes);
    return nullptr;
  } catch (const std::runtime_error& error) {
    return std::make_exception_ptr(std::invalid_argument(option_ + ": " + error.what()));
  } catch (...) {
    return std::current_exception();
  }
}

// Writes every encoded frame whose turn has come. One thread at a time: the
// others leave their frames in encoded_ for it, and it looks again after
// each write, so no frame is left behind.
void PngWriterPool::writeInOrder(std::unique_lock<std::mutex>& lock) {
  if (writing_) return;
  writing_ = true;
  while (!failure_ && !encoded_.empty() && encoded_.begin()->first == written_) {
    const Encoded frame = std::move(encoded_.begin()->second);
    encoded_.erase(encoded_.begin());
    lock.unlock();
    const auto start = Clock::now();
    const std::exception_ptr failure = write(frame);
    const double seconds = secondsSince(start);
    lock.lock();
    times_.writeSeconds += seconds;
    if (failure) failure_ = failure;
    else ++written_;
  }
  writing_ = false;
  changed_.notify_all();
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
      if (failure_) continue;  // the run has failed: no file after the failed one
    }
    changed_.notify_all();
    Encoded frame = encode(job);
    std::unique_lock lock(mutex_);
    encoded_.emplace(job.sequence, std::move(frame));
    writeInOrder(lock);
  }
}

}  // namespace physdbg::viewer
