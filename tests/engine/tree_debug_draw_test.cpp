#include "engine/broadphase/tree_debug_draw.h"

#include <gtest/gtest.h>

#include "tests/engine/broad_phase_test_helpers.h"

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
