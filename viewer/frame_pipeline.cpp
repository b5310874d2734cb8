#include "viewer/frame_pipeline.h"

#include <chrono>
#include <ctime>
#include <optional>

#include "viewer/frame_prefetcher.h"
#include "viewer/png_writer_pool.h"
#include "viewer/scene_frames.h"

namespace physdbg::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

double processCpuSeconds() {
  timespec time{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &time);
  return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
}

// Process CPU time spent in `call`, added to `total`: a stage's own cost
// only while no other stage runs (serial runs).
template <typename Call>
decltype(auto) addCpuOf(double& total, Call&& call) {
  const double start = processCpuSeconds();
  struct Add {
    double& total;
    double start;
    ~Add() { total += processCpuSeconds() - start; }
  } add{total, start};
  return call();
}

// The frames in order: made here (serial) or taken from the prefetcher.
class FrameSource {
 public:
  // The producing thread alone adds to `times.produce` and `times.produceCpu`.
  FrameSource(const FramePipelineOptions& options, const ProduceFrame& produce, FrameStageTimes& times)
      : produce_([&produce, &times](int index) {
          const auto start = Clock::now();
          debugdraw::RecordedFrame frame = addCpuOf(times.produceCpu, [&] { return produce(index); });
          times.produce += secondsSince(start);
          return frame;
        }),
        next_(options.first),
        last_(options.last) {
    if (options.mode == PipelineMode::Pipelined)
      prefetcher_.emplace(options.first, options.last, options.framesAhead, produce_);
  }

  // Nothing after the last frame; by then the producing thread has ended.
  std::optional<debugdraw::RecordedFrame> next() {
    if (prefetcher_) return prefetcher_->next();
    if (next_ >= last_) return std::nullopt;
    return produce_(next_++);
  }

 private:
  std::function<debugdraw::RecordedFrame(int)> produce_;
  int next_, last_;
  std::optional<FramePrefetcher<debugdraw::RecordedFrame>> prefetcher_;  // last: stops before the rest dies
};

PoolSize poolSizeFor(const FramePipelineOptions& options, const render::Renderer& renderer) {
  if (options.mode == PipelineMode::Serial) return {0, 1};
  return framePoolSize(renderer.options().width, renderer.options().height);
}

void addRenderTimings(const render::RenderTimings& timings, FrameStageTimes& times) {
  times.prepare += timings.prepareSeconds;
  times.draw += timings.drawSeconds;
  times.readBack += timings.readBackSeconds;
}

}  // namespace

FrameStageTimes runFramePipeline(const FramePipelineOptions& options, const ProduceFrame& produce,
                                 render::Renderer& renderer, const FramePath& pathOf, const FrameDone& onFrameDone) {
  FrameStageTimes times, produced;
  const auto wallStart = Clock::now();
  const double cpuStart = processCpuSeconds();
  {
    PngWriterPool writers(poolSizeFor(options, renderer), options.outputOption);
    FrameSource source(options, produce, produced);  // after writers: stops first on a failure
    for (;;) {
      const auto waitStart = Clock::now();
      std::optional<debugdraw::RecordedFrame> frame = source.next();
      if (options.mode == PipelineMode::Pipelined) times.waitForFrame += secondsSince(waitStart);
      if (!frame) break;
      render::Image image =
          addCpuOf(times.renderCpu, [&] { return renderer.render(frame->frame, toCamera(frame->view)); });
      addRenderTimings(renderer.lastTimings(), times);
      addCpuOf(times.encodeCpu, [&] { writers.submit(pathOf(frame->index), std::move(image)); });
      ++times.frames;
      if (onFrameDone) onFrameDone(times.frames);
    }
    addCpuOf(times.encodeCpu, [&] { writers.finish(); });
    const PoolTimes pool = writers.times();
    times.encode = pool.encodeSeconds;
    times.write = pool.writeSeconds;
    times.waitForEncoder = options.mode == PipelineMode::Pipelined ? pool.submitWaitSeconds : 0;
  }
  times.produce = produced.produce;
  times.cpu = processCpuSeconds() - cpuStart;
  if (options.mode == PipelineMode::Serial) times.produceCpu = produced.produceCpu;
  else times.renderCpu = times.encodeCpu = 0;  // other threads ran meanwhile: no stage's own figure
  times.wall = secondsSince(wallStart);
  return times;
}

}  // namespace physdbg::viewer
