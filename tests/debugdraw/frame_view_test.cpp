// The viewer's selection (debugdraw/frame_view.h) on small hand-made frames:
// layers and tree depths from tags, the focus on highlighted bodies (their
// contacts and pairs even when those layers are off, the tree path to the
// root), labels within the text budget, and refusal of untagged frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "debugdraw/frame_view.h"

namespace dd = physdbg::debugdraw;
using dd::Layer;
using dd::Vec3;

namespace {

dd::Tag treeTag(int node, int parent, int depth) {
  dd::Tag tag = dd::tagOf(Layer::Tree);
  tag.node = node;
  tag.parent = parent;
  tag.depth = depth;
  return tag;
}

dd::BodyInfo body(int index, Vec3 centre, int treeParent) {
  dd::BodyInfo info;
  info.index = index;
  info.position = centre;
  info.boundsMin = centre - Vec3::Constant(0.5);
  info.boundsMax = centre + Vec3::Constant(0.5);
  info.treeLeaf = 10 + index;
  info.treeParent = treeParent;
  return info;
}

// Three boxes; 0 and 1 touch. Tree: root 1 -> {2 -> {leaf 10, leaf 11}, leaf 12}.
dd::Frame threeBoxes() {
  dd::Frame frame;
  const dd::Color white{1, 1, 1, 1};
  for (int i = 0; i < 3; ++i) {
    frame.boxes.push_back({Vec3(2.0 * i, 0, 0), dd::Quat::Identity(), Vec3::Constant(0.5), white, dd::tagOf(Layer::Shapes, i)});
    frame.bodies.push_back(body(i, Vec3(2.0 * i, 0, 0), i < 2 ? 2 : 1));
  }
  frame.points.push_back({Vec3(1, 0, 0), 7, dd::colors::contactPoint, dd::tagOf(Layer::Contacts, 0, 1)});
  frame.lines.push_back({Vec3(0, 0, 0), Vec3(2, 0, 0), white, dd::tagOf(Layer::Pairs, 0, 1)});
  frame.lines.push_back({Vec3(2, 0, 0), Vec3(4, 0, 0), white, dd::tagOf(Layer::Pairs, 1, 2)});
  frame.wireBoxes.push_back({Vec3(2, 0, 0), dd::Quat::Identity(), Vec3(3, 1, 1), dd::colors::treeNode, treeTag(1, -1, 0)});
  frame.wireBoxes.push_back({Vec3(1, 0, 0), dd::Quat::Identity(), Vec3(2, 1, 1), dd::colors::treeNode, treeTag(2, 1, 1)});
  frame.texts.push_back({6, 64, 1, "tree depth", white, treeTag(-1, -1, -1)});
  frame.texts.push_back({6, 75, 1, "1  1 box", white, treeTag(-1, -1, 1)});
  frame.texts.push_back({6, 6, 1, "overlay", white, dd::tagOf(Layer::Overlay)});
  return frame;
}

dd::ViewSelection showing(const char* layers) {
  dd::ViewSelection selection;
  selection.layers = dd::parseLayers(layers);
  return selection;
}

bool isFaded(dd::Color shown, dd::Color original) { return shown.r < original.r * 0.6f; }

}  // namespace

TEST(FrameView, KeepsOnlyTheChosenLayers) {
  const dd::Frame shown = dd::selectView(threeBoxes(), showing("shapes"));
  EXPECT_EQ(shown.boxes.size(), 3u);
  EXPECT_TRUE(shown.points.empty());
  EXPECT_TRUE(shown.lines.empty());
  EXPECT_TRUE(shown.wireBoxes.empty());
  EXPECT_TRUE(shown.texts.empty());
  EXPECT_EQ(dd::selectView(threeBoxes(), showing("pairs,overlay")).lines.size(), 2u);
}

TEST(FrameView, TreeDepthSelectsNodesAndTheirLegendLines) {
  dd::ViewSelection selection = showing("tree");
  selection.treeMinDepth = 1;
  const dd::Frame shown = dd::selectView(threeBoxes(), selection);
  ASSERT_EQ(shown.wireBoxes.size(), 1u);
  EXPECT_EQ(shown.wireBoxes[0].tag.node, 2);
  EXPECT_EQ(shown.texts.size(), 2u);  // header and depth 1
  selection.treeMinDepth = 0;
  selection.treeMaxDepth = 0;
  const dd::Frame root = dd::selectView(threeBoxes(), selection);
  ASSERT_EQ(root.wireBoxes.size(), 1u);
  EXPECT_EQ(root.wireBoxes[0].tag.node, 1);
  EXPECT_EQ(root.texts.size(), 1u);  // the header only
}

TEST(FrameView, HighlightFadesOthersAndShowsContactsPairsAndTreePath) {
  dd::ViewSelection selection = showing("shapes,overlay");
  selection.highlight = {0};
  const dd::Frame original = threeBoxes();
  const dd::Frame shown = dd::selectView(original, selection);
  // Body 0 as it was; 1 and 2 faded.
  ASSERT_EQ(shown.boxes.size(), 3u);
  EXPECT_FALSE(isFaded(shown.boxes[0].color, original.boxes[0].color));
  EXPECT_TRUE(isFaded(shown.boxes[1].color, original.boxes[1].color));
  EXPECT_TRUE(isFaded(shown.boxes[2].color, original.boxes[2].color));
  // Its contact and its pair with 1 though neither layer is shown; not the pair 1-2.
  ASSERT_EQ(shown.points.size(), 1u);
  ASSERT_EQ(shown.lines.size(), 1u);
  EXPECT_EQ(shown.lines[0].tag.otherBody, 1);
  // The tree path 2 -> 1 in the focus colour, and a focus box round the body.
  int pathNodes = 0, focusBoxes = 0;
  for (const dd::WireBox& box : shown.wireBoxes) {
    if (box.tag.layer == static_cast<std::uint32_t>(Layer::Tree)) ++pathNodes;
    if (box.tag.layer == 0 && box.color.r == dd::focusColor.r && box.color.g == dd::focusColor.g) ++focusBoxes;
  }
  EXPECT_EQ(pathNodes, 2);
  EXPECT_EQ(focusBoxes, 1);
  // The tree legend stays out (tree not shown); the overlay gains the body's line.
  const bool bodyLine = std::any_of(shown.texts.begin(), shown.texts.end(),
                                    [](const dd::Text& text) { return text.text.rfind("body 0", 0) == 0; });
  EXPECT_TRUE(bodyLine);
  EXPECT_EQ(shown.texts.size(), 3u);  // overlay, and two lines on body 0
}

TEST(FrameView, HighlightOfABodyTheFrameLacksIsRefused) {
  dd::ViewSelection selection = showing("shapes");
  selection.highlight = {7};
  try {
    dd::selectView(threeBoxes(), selection);
    FAIL() << "expected a refusal";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("no body 7"), std::string::npos) << error.what();
  }
}

// A body out of the run at this frame (added later, or removed) has no
// shape to box, label or bracket: the overlay says it is absent instead.
TEST(FrameView, AbsentBodyIsSaidAbsentNotBoxedLabelledOrBracketed) {
  dd::Frame frame = threeBoxes();
  frame.boxes.erase(frame.boxes.begin() + 2);
  frame.bodies[2].absent = true;
  dd::ViewSelection selection = showing("shapes,overlay");
  selection.highlight = {2};
  selection.labels = true;
  selection.follow = 2;
  const dd::Frame shown = dd::selectView(frame, selection);
  for (const dd::WireBox& box : shown.wireBoxes) EXPECT_NE(box.tag.layer, 0u) << "no focus box";
  for (const dd::Line& line : shown.lines) EXPECT_NE(line.tag.layer, 0u) << "no follow brackets";
  ASSERT_EQ(shown.labels.size(), 2u);
  for (const dd::Label& label : shown.labels) EXPECT_NE(label.text, "2");
  const bool saysAbsent = std::any_of(shown.texts.begin(), shown.texts.end(), [](const dd::Text& text) {
    return text.text.rfind("body 2", 0) == 0 && text.text.find("absent") != std::string::npos;
  });
  EXPECT_TRUE(saysAbsent);
}

TEST(FrameView, LabelsNameEveryBodyAndHighlightedFirst) {
  dd::Frame frame = threeBoxes();
  frame.bodies[2].name = "lid";
  dd::ViewSelection selection = showing("shapes");
  selection.labels = true;
  selection.highlight = {2};
  const dd::Frame shown = dd::selectView(frame, selection);
  ASSERT_EQ(shown.labels.size(), 3u);
  EXPECT_EQ(shown.labels[0].text, "2 lid");
  EXPECT_EQ(shown.labels[1].text, "0");
  EXPECT_EQ(shown.labels[2].text, "1");
}

TEST(FrameView, LabelsBeyondTheTextBudgetAreCountedNotDrawn) {
  dd::Frame frame;
  for (int i = 0; i < 10000; ++i) frame.bodies.push_back(body(i, Vec3(i, 0, 0), -1));
  dd::ViewSelection selection = showing("shapes");
  selection.labels = true;
  dd::ViewReport report;
  const dd::Frame shown = dd::selectView(frame, selection, &report);
  std::size_t characters = 0;
  for (const dd::Label& label : shown.labels) characters += label.text.size();
  EXPECT_LE(characters, dd::maxFrameTextCharacters);
  EXPECT_GT(report.labelsLeftOut, 0);
  EXPECT_EQ(static_cast<int>(shown.labels.size()) + report.labelsLeftOut, 10000);
}

TEST(FrameView, FollowedBodyGetsCornerBrackets) {
  dd::ViewSelection selection = showing("shapes");
  selection.follow = 1;
  const dd::Frame shown = dd::selectView(threeBoxes(), selection);
  EXPECT_EQ(shown.lines.size(), 24u);
  for (const dd::Line& line : shown.lines) {
    EXPECT_NEAR(line.from.x(), 2.0, 0.5 + 1e-12);  // on body 1's box
    EXPECT_NEAR((line.to - line.from).norm(), 0.3, 1e-12);
  }
}

TEST(FrameView, UntaggedFramesAreRefused) {
  dd::Frame frame = threeBoxes();
  frame.boxes[1].tag = dd::Tag{};
  EXPECT_THROW(dd::selectView(frame, showing("shapes")), std::invalid_argument);
}

TEST(FrameView, HighlightNeedsTheRelationLayers) {
  dd::ViewSelection selection = showing("shapes");
  selection.highlight = {0};
  const dd::LayerSet needed = dd::layersNeeded(selection);
  for (Layer layer : {Layer::Shapes, Layer::Contacts, Layer::Pairs, Layer::Tree, Layer::Fat}) EXPECT_TRUE(needed.has(layer));
  EXPECT_FALSE(dd::layersNeeded(showing("shapes")).has(Layer::Tree));
}
