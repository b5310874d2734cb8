#pragma once
// A run of rendered frames in three stages that overlap: each frame's physics
// and primitives (`produce`) on a thread of their own, a few frames ahead;
// drawing and read-back on the calling thread, which keeps the GL context;
// PNG encoding on a pool that writes the files in frame order. Serial runs
// every stage on the calling thread, one frame after another: the same bytes
// (tested), and each stage's time without the others competing for the cores.
#include <functional>
#include <string>

#include "debugdraw/recording.h"
#include "render/renderer.h"

namespace physdbg::viewer {

enum class PipelineMode { Serial, Pipelined };

struct FramePipelineOptions {
  PipelineMode mode = PipelineMode::Pipelined;
  int first = 0, last = 0;          // frames first..last-1
  std::size_t framesAhead = 2;      // snapshots the producer may hold ready
  std::string outputOption = "-o";  // named in a failed write's message
};

// Seconds summed over the run's frames. The two waits say what bounds a
// pipelined run: the drawing thread waits for frames when physics is slower
// than drawing, for room in the encoder's queue when encoding is.
struct FrameStageTimes {
  int frames = 0;
  double produce = 0;                         // physics and primitives (the producing thread)
  double prepare = 0, draw = 0, readBack = 0;  // render::RenderTimings
  double encode = 0, write = 0;               // summed over the encoding threads
  double waitForFrame = 0, waitForEncoder = 0;
  double wall = 0;
  // Process CPU time, every thread of ours and llvmpipe's: of the whole run,
  // and (serial runs only, where one stage runs at a time) of each stage.
  // Unlike wall times these hold on a loaded machine, and on C cores a
  // pipelined run cannot beat C / (CPU seconds per frame) frames per second.
  double cpu = 0, produceCpu = 0, renderCpu = 0, encodeCpu = 0;
};

using ProduceFrame = std::function<debugdraw::RecordedFrame(int index)>;
using FramePath = std::function<std::string(int index)>;
using FrameDone = std::function<void(int framesDone)>;

// Throws what `produce` or the renderer throws, and std::invalid_argument
// naming the output option and the file for a frame that cannot be written;
// the other threads are stopped and joined first, and frames before a failed
// write are complete on disk.
FrameStageTimes runFramePipeline(const FramePipelineOptions& options, const ProduceFrame& produce,
                                 render::Renderer& renderer, const FramePath& pathOf,
                                 const FrameDone& onFrameDone = {});

}  // namespace physdbg::viewer
