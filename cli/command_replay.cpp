// physdbg replay: renders a recording to PNGs with no engine involved. A
// frame range lets several processes share one long recording.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/common_options.h"
#include "cli/output_folder.h"
#include "cli/view_options.h"
#include "debugdraw/recording.h"
#include "render/renderer.h"
#include "viewer/png_writer_pool.h"
#include "viewer/scene_camera.h"
#include "viewer/scene_frames.h"

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

// The viewer's choices for a recording: none given keeps each frame as recorded.
struct ReplayView {
  std::optional<debugdraw::LayerSet> layers;  // --layers; else the layers the recording run showed
  ViewOptions options;                        // focus, tree depth, camera, size
  bool changesFrames() const {
    return layers || !options.highlight.empty() || options.labels || options.camera.any() ||
           options.treeMinDepth > 0 || options.treeMaxDepth < (1 << 30);
  }
};

ReplayView readReplayView(const Arguments& arguments) {
  ReplayView view;
  ViewOptions& options = view.options;
  std::tie(options.width, options.height) = readSize(arguments, defaultImageSize);
  if (arguments.has("--layers")) view.layers = readLayers(arguments, "");
  options.layers = view.layers.value_or(viewer::allLayerSet());
  readTreeDepth(arguments, options, view.layers ? "--layers" : "the recording");
  readDrawChoices(arguments, options);
  return view;
}

// Version 1 primitives carry no layer or body: nothing to choose from.
void checkTagged(const debugdraw::RecordingReader& reader, const ReplayView& view, const std::string& path) {
  if (reader.version() >= 2 || !view.changesFrames()) return;
  throw UsageError("'" + path + "' is a version " + std::to_string(reader.version()) +
                   " recording: its primitives carry no layer or body tags, so --layers, --tree-depth, "
                   "--highlight, --labels and the camera options need it recorded again with this physdbg");
}

// Draws recorded frames with the viewer's choices, as `render` would have
// drawn them with the same options (the same selection, the same camera rule).
class ReplayViewer {
 public:
  ReplayViewer(const ReplayView& view, std::uint32_t version) : view_(view), tagged_(version >= 2) {}

  // Version 2 frames hold every layer: the selection picks what is shown.
  debugdraw::RecordedFrame show(const debugdraw::RecordedFrame& recorded) {
    if (!tagged_) return recorded;
    debugdraw::ViewSelection selection = selectionOf(view_.options);
    selection.layers = view_.layers.value_or(recorded.shownLayers);
    // --tree-depth against the recorded layers: without tree it would draw nothing.
    if (!view_.layers && (view_.options.treeMinDepth > 0 || view_.options.treeMaxDepth < (1 << 30)) &&
        !selection.layers.has(debugdraw::Layer::Tree))
      throw UsageError("--tree-depth: it limits the 'tree' layer, which the recording run did not show (" +
                       debugdraw::layerNames(selection.layers) + "); add --layers with tree");
    debugdraw::RecordedFrame shown;
    shown.index = recorded.index;
    try {
      debugdraw::ViewReport report;
      shown.frame = debugdraw::selectView(recorded.frame, selection, &report);
      labelsLeftOut_ = std::max(labelsLeftOut_, report.labelsLeftOut);
    } catch (const std::invalid_argument& error) {
      throw UsageError("frame " + std::to_string(recorded.index) + ": " + error.what());
    }
    shown.view = viewer::toView(camera(recorded));
    return shown;
  }
  int labelsLeftOut() const { return labelsLeftOut_; }

 private:
  const debugdraw::BodyInfo* followed(const debugdraw::RecordedFrame& recorded) const {
    if (!view_.options.camera.follow) return nullptr;
    for (const debugdraw::BodyInfo& body : recorded.frame.bodies)
      if (body.index == *view_.options.camera.follow) return &body;
    throw UsageError("--follow: frame " + std::to_string(recorded.index) + " has no body " +
                     std::to_string(*view_.options.camera.follow) + " (it has " +
                     std::to_string(recorded.frame.bodies.size()) + ")");
  }

  render::Camera camera(const debugdraw::RecordedFrame& recorded) {
    if (!view_.options.camera.any()) return viewer::toCamera(recorded.view);
    const debugdraw::BodyInfo* body = followed(recorded);
    if (!initialCamera_) {
      const double aspect = static_cast<double>(view_.options.width) / view_.options.height;
      initialCamera_ = asUsageError(
          [&] { return viewer::applyCameraOptions(viewer::toCamera(recorded.view), view_.options.camera, body, aspect); });
    }
    return body ? viewer::followBody(*initialCamera_, *body) : *initialCamera_;
  }

  ReplayView view_;
  bool tagged_;
  std::optional<render::Camera> initialCamera_;
  int labelsLeftOut_ = 0;
};

}  // namespace

int runReplay(const std::vector<std::string>& args) {
  CommandSpec spec{
      "replay",
      "FILE -o DIR [--frames N|A:B] [--size WxH] [--layers LIST] [--highlight A,B] [--labels] [camera options]\n"
      "       [--backend osmesa|egl]",
      "Renders the frames of a recording made by 'physdbg record' to DIR/frame_NNNNN.png, numbered as\n"
      "recorded. With --frames A:B only recorded frames A..B-1 are decoded and drawn. With no view option\n"
      "each frame is drawn as the recording run showed it; --layers, --tree-depth, --highlight, --labels and\n"
      "the camera options draw it as 'physdbg render' would have with them.",
      {outputOption("DIR", "output folder (required)")},
      1,
      1};
  addOptions(spec, {OptionGroup::RecordedFrames, OptionGroup::ImageSize, OptionGroup::RecordedLayers,
                    OptionGroup::Focus, OptionGroup::Camera, OptionGroup::Backend});
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  const std::string directory = requiredOutput(*parsed, "DIR");
  const FrameRange range = readFrames(*parsed).value_or(FrameRange{0, std::numeric_limits<int>::max()});
  const ReplayView view = readReplayView(*parsed);
  const int width = view.options.width, height = view.options.height;
  debugdraw::RecordingReader reader(parsed->positional()[0]);
  checkTagged(reader, view, parsed->positional()[0]);
  ReplayViewer replayViewer(view, reader.version());
  prepareOutputDirectory(directory);

  render::Renderer renderer({width, height, view.options.samples, readBackend(*parsed)});
  viewer::PngWriterPool writers(viewer::framePoolSize(width, height), "-o");
  debugdraw::RecordedFrame frame;
  int written = 0;
  while (reader.next(frame, range.first, range.last)) {
    const debugdraw::RecordedFrame shown = replayViewer.show(frame);
    render::Image image = renderer.render(shown.frame, viewer::toCamera(shown.view));
    asUsageError([&] { writers.submit(framePath(directory, frame.index), std::move(image)); });
    ++written;
  }
  asUsageError([&] { writers.finish(); });
  checkSomethingReplayed(written, parsed->positional()[0], *parsed);
  std::printf("replayed %d frames to %s\n", written, directory.c_str());
  viewer::reportLabelsLeftOut("replay", replayViewer.labelsLeftOut());
  return 0;
}

}  // namespace physdbg::cli
