// physdbg replay: renders a recording to PNGs with no engine involved. A
// frame range lets several processes share one long recording.
#include <algorithm>
#include <cstdio>
#include <limits>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/output_folder.h"
#include "cli/png_writer_pool.h"
#include "cli/scene_frames.h"
#include "cli/view_options.h"
#include "debugdraw/recording.h"
#include "render/renderer.h"

namespace physdbg::cli {
namespace {

// "frames 0..59 (60 frames)", "no frames": read in full, only when a replay
// drew nothing, to say what the recording holds instead.
std::string describeFrames(const std::string& path) {
  debugdraw::RecordingReader reader(path);
  debugdraw::RecordedFrame frame;
  int count = 0, lowest = std::numeric_limits<int>::max(), highest = -1;
  while (reader.next(frame)) {
    ++count;
    lowest = std::min(lowest, frame.index);
    highest = std::max(highest, frame.index);
  }
  if (count == 0) return "no frames";
  return "frames " + std::to_string(lowest) + ".." + std::to_string(highest) + " (" + std::to_string(count) +
         (count == 1 ? " frame)" : " frames)");
}

// A replay that drew no frame leaves the user a folder of nothing: refuse it.
void checkSomethingReplayed(int written, const std::string& path, const Arguments& arguments) {
  if (written > 0) return;
  const std::string holds = "'" + path + "' has " + describeFrames(path);
  if (arguments.has("--frames"))
    throw UsageError("--frames: '" + arguments.value("--frames") + "' selects no frame of the recording; " + holds);
  throw UsageError(holds);
}

}  // namespace

int runReplay(const std::vector<std::string>& args) {
  const CommandSpec spec{
      "replay",
      "FILE -o DIR [--frames N|A:B] [--size WxH] [--backend osmesa|egl]",
      "Renders the frames of a recording made by 'physdbg record' to DIR/frame_NNNNN.png, numbered as\n"
      "recorded. With --frames A:B only recorded frames A..B-1 are decoded and drawn.",
      {{"--output", "-o", "DIR", "output folder (required)"},
       {"--frames", "", "N|A:B", "frames 0..N-1 or A..B-1 (default all)"},
       {"--size", "", "WxH", "image size in pixels (default 1280x720)"},
       backendOptionSpec()},
      1,
      1};
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  if (!parsed->has("--output")) throw UsageError("-o DIR is required");
  FrameRange range{0, std::numeric_limits<int>::max()};
  if (parsed->has("--frames")) range = parseFrameRange(parsed->value("--frames"), "--frames");
  const auto [width, height] = parseSize(parsed->value("--size", "1280x720"), "--size");
  debugdraw::RecordingReader reader(parsed->positional()[0]);
  const std::string directory = parsed->value("--output");
  prepareOutputDirectory(directory);

  render::Renderer renderer({width, height, 0, readBackend(*parsed)});
  PngWriterPool writers(framePoolSize(width, height), "-o");
  debugdraw::RecordedFrame frame;
  int written = 0;
  while (reader.next(frame, range.first, range.last)) {
    writers.submit(framePath(directory, frame.index), renderer.render(frame.frame, toCamera(frame.view)));
    ++written;
  }
  writers.finish();
  checkSomethingReplayed(written, parsed->positional()[0], *parsed);
  std::printf("replayed %d frames to %s\n", written, directory.c_str());
  return 0;
}

}  // namespace physdbg::cli
