#include "engine/broadphase/tree_debug_draw.h"

#include <gtest/gtest.h>

#include "tests/engine/broadphase/broad_phase_test_helpers.h"

namespace physdbg {
namespace {

TEST(TreeDebugDraw, DrawsEveryNodeOnceAndHonoursDepthAndKinds) {
  DynamicAabbTree tree;
  for (const Aabb& box : testing::sortedGrid(8)) tree.createProxy(box, 0);
  debugdraw::Frame all;
  drawTree(tree, {}, all);
  EXPECT_EQ(static_cast<int>(all.wireBoxes.size()), tree.nodeCount());

  debugdraw::Frame leavesOnly;
  drawTree(tree, {false, true, 1 << 30}, leavesOnly);
  EXPECT_EQ(static_cast<int>(leavesOnly.wireBoxes.size()), tree.proxyCount());

  debugdraw::Frame top;
  drawTree(tree, {true, true, 1}, top);
  EXPECT_EQ(top.wireBoxes.size(), 3u);  // root and its two children
  EXPECT_FLOAT_EQ(top.wireBoxes[0].color.a, 1.0f);
  EXPECT_LT(top.wireBoxes[1].color.a, 1.0f);
  const Aabb& root = tree.box(tree.root());
  EXPECT_TRUE(top.wireBoxes[0].center.isApprox(root.center()));
  EXPECT_TRUE(top.wireBoxes[0].halfExtents.isApprox(root.halfExtents()));

  debugdraw::Frame band;
  drawTree(tree, {true, false, 2, 1}, band);
  EXPECT_EQ(band.wireBoxes.size(), 6u);  // the two children of the root and their four children
}

TEST(TreeDebugDraw, DeeperNodesArePalerNotOnlyMoreTransparent) {
  for (int depth = 0; depth < 12; ++depth) {
    const debugdraw::Color shallow = treeNodeColor(depth), deep = treeNodeColor(depth + 1);
    EXPECT_GT(deep.r, shallow.r) << depth;
    EXPECT_GT(deep.g, shallow.g) << depth;
    EXPECT_GE(deep.a, 0.7f) << depth;  // fades a little, so paler wins over darker
  }
  EXPECT_GT(treeNodeColor(2).r - treeNodeColor(0).r, 0.15f);  // near the root a level is a clear step
}

// A big box with a chain of ever smaller boxes inside it: with the same
// bounds twice (two leaves spanning the whole), a node repeats its parent's box.
TEST(TreeDebugDraw, LegendNamesEachDrawnDepthAndRepeatedParentBoxes) {
  DynamicAabbTree tree;
  tree.createProxy(Aabb{Vec3(0, 0, 0), Vec3(10, 1, 10)}, 0);   // a floor
  tree.createProxy(Aabb{Vec3(0, 0, 0), Vec3(1, 10, 10)}, 0);   // a wall on it
  tree.createProxy(Aabb{Vec3(9, 0, 0), Vec3(10, 10, 10)}, 0);  // the opposite wall
  tree.createProxy(Aabb{Vec3(4, 1, 4), Vec3(5, 2, 5)}, 0);     // a ball
  debugdraw::Frame frame;
  drawTree(tree, {true, false}, frame);
  ASSERT_GE(frame.texts.size(), 2u);
  EXPECT_EQ(frame.texts[0].text, "tree depth");
  EXPECT_EQ(frame.texts[1].text.rfind("0  1 box", 0), 0u) << frame.texts[1].text;
  bool repeated = false;
  for (const debugdraw::Text& text : frame.texts) repeated = repeated || text.text.find("parent's box") != std::string::npos;
  EXPECT_TRUE(repeated);  // walls and floor span the whole: some node has its parent's box

  TreeDrawOptions quiet{true, false};
  quiet.legend = false;
  debugdraw::Frame noLegend;
  drawTree(tree, quiet, noLegend);
  EXPECT_TRUE(noLegend.texts.empty());
}

TEST(TreeDebugDraw, DrawsTwoBoxesAndALinePerRotation) {
  DynamicAabbTree tree;
  tree.setRotationLogEnabled(true);
  for (const Aabb& box : testing::sortedRow(32)) tree.createProxy(box, 0);
  ASSERT_FALSE(tree.rotationLog().empty());
  debugdraw::Frame frame;
  drawRotations(tree.rotationLog(), frame);
  EXPECT_EQ(frame.wireBoxes.size(), 2 * tree.rotationLog().size());
  EXPECT_EQ(frame.lines.size(), tree.rotationLog().size());
  const RotationEvent& event = tree.rotationLog().front();
  EXPECT_TRUE(frame.wireBoxes[0].center.isApprox(event.firstBox.center()));
  EXPECT_GT(event.firstBox.surfaceArea(), 0.0);
}

}  // namespace
}  // namespace physdbg
