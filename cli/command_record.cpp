// physdbg record: simulates a scene and writes every frame's primitives and
// view to a recording (debugdraw/recording.h), without rendering.
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/numerical_faults.h"
#include "cli/output_folder.h"
#include "cli/progress_bar.h"
#include "cli/view_options.h"
#include "debugdraw/recording.h"
#include "scenes/scene.h"
#include "viewer/scene_frames.h"

namespace physdbg::cli {
namespace {

// -o missing/dir/x.rec creates missing/dir, as render creates its -o folder.
// An existing folder is left to the writer, which names the path on failure.
void createParentFolder(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!folder.empty() && !std::filesystem::exists(folder, error)) prepareOutputDirectory(folder.string(), "-o");
}

}  // namespace

int runRecord(const std::vector<std::string>& args) {
  CommandSpec spec{
      "record",
      "SCENE -o FILE [--frames N|A:B] [--size WxH] [--layers LIST] [--steps-per-frame K] [camera options]",
      "Simulates SCENE and writes the debug-draw primitives of every layer, each body's state and the view\n"
      "of every frame to FILE (format: debugdraw/RECORDING.md). 'physdbg replay FILE' renders it later,\n"
      "showing --layers unless told otherwise, and can choose other layers, --highlight, --labels and the\n"
      "camera then. --size sets the aspect the camera frames for.",
      {outputOption("FILE", "recording to write (required)")},
      1,
      1};
  addOptions(spec, {OptionGroup::SceneFrames, OptionGroup::ImageSize, OptionGroup::SceneLayers, OptionGroup::Camera,
                    OptionGroup::Solver, OptionGroup::Threads});
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const std::string path = requiredOutput(*parsed, "FILE");
  const SceneDescription scene = readScene(*parsed);
  const ViewOptions options = readViewOptions(*parsed, scene);
  createParentFolder(path);
  std::unique_ptr<debugdraw::RecordingWriter> writer;
  try {
    writer = std::make_unique<debugdraw::RecordingWriter>(path);
  } catch (const std::runtime_error& error) {
    throw UsageError(std::string("-o: ") + error.what());
  }
  viewer::SceneFrames frames =
      asUsageError([&] { return viewer::SceneFrames(scene, options, viewer::FramePurpose::Record); });
  ProgressBar progress("record " + scene.name, options.frames.count());
  for (int index = options.frames.first; index < options.frames.last; ++index) {
    writer->write(frames.frame(index));
    progress.update(index - options.frames.first + 1);
  }
  try {
    writer->close();
  } catch (const std::runtime_error& error) {
    throw UsageError(std::string("-o: ") + error.what());
  }
  progress.finish();
  std::printf("recorded frames %d..%d of %s to %s\n", options.frames.first, options.frames.last - 1,
              scene.name.c_str(), path.c_str());
  viewer::reportBlankLayers("record", options, frames.layerCounts());
  return reportNumericalFaults("record", frames.world());
}

}  // namespace physdbg::cli
