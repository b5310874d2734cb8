#include "viewer/view_options.h"

namespace physdbg::viewer {

debugdraw::ViewSelection selectionOf(const ViewOptions& options) {
  debugdraw::ViewSelection selection;
  selection.layers = options.layers;
  selection.treeMinDepth = options.treeMinDepth;
  selection.treeMaxDepth = options.treeMaxDepth;
  selection.highlight = options.highlight;
  selection.labels = options.labels;
  selection.follow = options.camera.follow;
  selection.imageWidth = options.width;
  selection.imageHeight = options.height;
  return selection;
}

}  // namespace physdbg::viewer
