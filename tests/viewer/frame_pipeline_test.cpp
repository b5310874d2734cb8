// The frame pipeline (viewer/frame_pipeline.h): physics on its own thread, a
// few frames ahead, and PNG encoding on a pool, give the same file bytes as
// one thread doing one stage after another; a failed write or a failed frame
// stops the run with the error, every thread joined, files before the failure
// complete and none after it.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "../support/visual_test_support.h"
#include "render/renderer.h"
#include "scenes/scene.h"
#include "viewer/bounded_queue.h"
#include "viewer/frame_pipeline.h"
#include "viewer/frame_prefetcher.h"
#include "viewer/scene_frames.h"

namespace {

namespace dd = physdbg::debugdraw;
namespace fs = std::filesystem;
using physdbg::visualtesting::fileBytes;
using physdbg::visualtesting::ScratchFolder;
using physdbg::viewer::PipelineMode;

constexpr int kFrames = 6;

physdbg::viewer::ViewOptions smallRun() {
  physdbg::viewer::ViewOptions options;
  options.frames = {0, kFrames};
  options.runFrames = kFrames;
  options.stepsPerFrame = 8;
  options.width = 160;
  options.height = 120;
  options.layers = dd::parseLayers("shapes,aabbs,fat,tree,contacts,velocities,pairs,overlay");
  options.timing = false;
  return options;
}

std::string framePath(const std::string& folder, int index) {
  return (fs::path(folder) / ("frame_" + std::to_string(index) + ".png")).string();
}

// `render`'s frames of the default scene into `folder`.
physdbg::viewer::FrameStageTimes renderRun(PipelineMode mode, const std::string& folder) {
  fs::create_directories(folder);
  const physdbg::SceneDescription scene = physdbg::resolveScene("default");
  const physdbg::viewer::ViewOptions options = smallRun();
  physdbg::viewer::SceneFrames frames(scene, options);
  physdbg::render::Renderer renderer({options.width, options.height, 0});
  physdbg::viewer::FramePipelineOptions pipeline;
  pipeline.mode = mode;
  pipeline.last = kFrames;
  return physdbg::viewer::runFramePipeline(
      pipeline, [&](int index) { return frames.frame(index); }, renderer,
      [&](int index) { return framePath(folder, index); });
}

TEST(FramePipeline, PipelinedFramesAreByteIdenticalToSerialOnes) {
  ScratchFolder scratch;
  const auto serial = renderRun(PipelineMode::Serial, scratch / "serial");
  const auto pipelined = renderRun(PipelineMode::Pipelined, scratch / "pipelined");
  EXPECT_EQ(serial.frames, kFrames);
  EXPECT_EQ(pipelined.frames, kFrames);
  for (int index = 0; index < kFrames; ++index) {
    const std::string bytes = fileBytes(framePath(scratch / "serial", index));
    EXPECT_GT(bytes.size(), 100u) << index;
    EXPECT_EQ(bytes, fileBytes(framePath(scratch / "pipelined", index))) << index;
  }
  // The run moves: equal files are not equal blank pictures.
  EXPECT_NE(fileBytes(framePath(scratch / "serial", 0)), fileBytes(framePath(scratch / "serial", kFrames - 1)));
}

TEST(FramePipeline, AFrameThatCannotBeWrittenStopsTheRunAfterTheFramesBeforeIt) {
  for (const PipelineMode mode : {PipelineMode::Serial, PipelineMode::Pipelined}) {
    ScratchFolder scratch;
    const std::string folder = scratch / "out";
    fs::create_directories(framePath(folder, 2));  // a folder where frame 2 belongs
    try {
      renderRun(mode, folder);
      ADD_FAILURE() << "no error";
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("-o: ", 0), 0u) << message;
      EXPECT_NE(message.find(framePath(folder, 2)), std::string::npos) << message;
    }
    EXPECT_TRUE(fs::is_regular_file(framePath(folder, 0)));
    EXPECT_TRUE(fs::is_regular_file(framePath(folder, 1)));
    for (int index = 3; index < kFrames; ++index) EXPECT_FALSE(fs::exists(framePath(folder, index))) << index;
  }
}

TEST(FramePipeline, AFrameThatFailsToBuildStopsTheRunWithItsError) {
  ScratchFolder scratch;
  physdbg::render::Renderer renderer({32, 24, 0});
  physdbg::viewer::FramePipelineOptions pipeline;
  pipeline.last = 1000;
  std::atomic<int> produced = 0;
  auto produce = [&](int index) {
    ++produced;
    if (index == 3) throw std::runtime_error("frame 3 is broken");
    dd::RecordedFrame frame;
    frame.index = index;
    frame.view.eye = Eigen::Vector3d(0, 0, 5);
    return frame;
  };
  EXPECT_THROW(
      {
        try {
          physdbg::viewer::runFramePipeline(pipeline, produce, renderer,
                                            [&](int index) { return framePath(scratch / "", index); });
        } catch (const std::runtime_error& error) {
          EXPECT_STREQ(error.what(), "frame 3 is broken");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(produced.load(), 4);
  EXPECT_TRUE(fs::is_regular_file(framePath(scratch / "", 2)));
}

TEST(FramePrefetcher, GivesEveryFrameInOrderAndStopsWhenDroppedEarly) {
  {
    physdbg::viewer::FramePrefetcher<int> frames(5, 9, 2, [](int index) { return index * 10; });
    for (int expected = 5; expected < 9; ++expected) EXPECT_EQ(frames.next(), expected * 10);
    EXPECT_FALSE(frames.next());
    EXPECT_FALSE(frames.next());
  }
  std::atomic<int> produced = 0;
  {
    physdbg::viewer::FramePrefetcher<int> frames(0, 1000000, 2, [&](int index) {
      ++produced;
      return index;
    });
    EXPECT_EQ(frames.next(), 0);
  }  // the producer, blocked on a full queue, is stopped and joined here
  EXPECT_LE(produced.load(), 5);
}

TEST(BoundedQueue, HoldsAtMostItsCapacityAndDrainsAfterClosing) {
  physdbg::viewer::BoundedQueue<int> queue(2);
  EXPECT_TRUE(queue.push(1));
  EXPECT_TRUE(queue.push(2));
  queue.close();
  EXPECT_FALSE(queue.push(3));
  EXPECT_EQ(queue.pop(), 1);
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_FALSE(queue.pop());
}

}  // namespace
