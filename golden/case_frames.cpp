#include "golden/case_frames.h"

#include <algorithm>

#include "viewer/scene_frames.h"

namespace physdbg::golden {
namespace {

// The view options render reads for `--frames A:B --no-timing` and the case's
// size, layers and camera (cli/view_options.cpp), A and B spanning the case's frames.
viewer::ViewOptions caseViewOptions(const ManifestCase& golden) {
  viewer::ViewOptions options;
  options.frames = {golden.frames.front(), golden.frames.back() + 1, true};
  options.runFrames = std::max(golden.scene.steps + 1, options.frames.last);
  options.width = golden.width;
  options.height = golden.height;
  options.layers = debugdraw::parseLayers(golden.layers);
  options.camera = golden.camera;
  options.timing = false;
  return options;
}

}  // namespace

std::vector<render::Image> renderCaseFrames(const ManifestCase& golden, RendererPool& renderers) {
  render::Renderer& renderer = renderers.forSize(golden.width, golden.height);
  viewer::SceneFrames frames(golden.scene, caseViewOptions(golden));
  std::vector<render::Image> images;
  for (const int index : golden.frames) {
    const debugdraw::RecordedFrame frame = frames.frame(index);
    images.push_back(renderer.render(frame.frame, viewer::toCamera(frame.view)));
  }
  return images;
}

}  // namespace physdbg::golden
