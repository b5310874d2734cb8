#pragma once
// The viewer's choices applied to a tagged frame: which layers and tree depths
// show, which bodies are in focus, labels and the follow marker. `render` and
// `replay` both go through here, so a replay with other options draws what a
// render with them would. Needs no engine: everything comes from the tags and
// the frame's BodyInfo list.
#include <optional>
#include <vector>

#include "debugdraw/primitives.h"

namespace physdbg::debugdraw {

struct ViewSelection {
  LayerSet layers;  // layers shown
  int treeMinDepth = 0, treeMaxDepth = 1 << 30;
  // Bodies in focus: drawn as they are, with their contacts, pairs and the
  // tree path from their leaf to the root; everything else faded.
  std::vector<int> highlight;
  bool labels = false;        // body index (and name) above each body
  std::optional<int> follow;  // this body gets a marker
  // Where screen text goes: a highlighted body's state is written at the
  // bottom left when the overlay layer is shown.
  int imageWidth = 1280, imageHeight = 720;
};

// What selectView had to leave out, for one line on stderr.
struct ViewReport {
  int labelsLeftOut = 0;  // labels beyond the frame's text budget (maxFrameTextCharacters)
};

// The colour of what is in focus: highlight boxes, the tree path to the root.
inline constexpr Color focusColor{1.0f, 0.72f, 0.0f, 1.0f};
// The follow marker's corner brackets.
inline constexpr Color followColor{1.0f, 1.0f, 1.0f, 1.0f};

// What a selection asks of a frame beyond its own layers: highlighting needs
// contacts, pairs and the tree to find what touches a body and its tree path.
LayerSet layersNeeded(const ViewSelection& selection);

// The frame to draw. Throws std::invalid_argument when `tagged` has no tags
// (a version 1 recording) and the selection needs them, or names a body the
// frame does not have.
Frame selectView(const Frame& tagged, const ViewSelection& selection, ViewReport* report = nullptr);

// Bodies the frame tags as touching `body` through a contact (any layer that
// tags pairs of bodies: contacts, impulses), sorted.
std::vector<int> contactPartners(const Frame& tagged, int body);

}  // namespace physdbg::debugdraw
