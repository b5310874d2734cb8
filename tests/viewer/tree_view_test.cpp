// The tree view's snapshot: undoing a refit walk's rotations must give a
// consistent tree over the same leaves whose internal area is larger by
// exactly what the rotations saved, and the diagram must show the swap.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "render/renderer.h"
#include "tests/support/render_test_support.h"
#include "viewer/pixel_canvas.h"
#include "viewer/tree_diagram.h"
#include "viewer/tree_snapshot.h"

namespace {

using namespace physdbg;
using physdbg::viewer::TreeSnapshot;

double internalArea(const TreeSnapshot& tree) {
  double area = 0;
  for (const TreeSnapshot::Node& node : tree.nodes)
    if (node.used && node.child1 != DynamicAabbTree::nullNode) area += node.box.surfaceArea();
  return area;
}

std::vector<int> leaves(const TreeSnapshot& tree) {
  std::vector<int> result;
  for (const int node : tree.subtree(tree.root))
    if (tree.isLeaf(node)) result.push_back(node);
  std::sort(result.begin(), result.end());
  return result;
}

void expectConsistent(const TreeSnapshot& tree) {
  for (const int node : tree.subtree(tree.root)) {
    if (tree.isLeaf(node)) continue;
    const TreeSnapshot::Node& n = tree.nodes[node];
    EXPECT_EQ(tree.nodes[n.child1].parent, node);
    EXPECT_EQ(tree.nodes[n.child2].parent, node);
    const Aabb merged = tree.nodes[n.child1].box.merged(tree.nodes[n.child2].box);
    EXPECT_EQ(n.box.min, merged.min);
    EXPECT_EQ(n.box.max, merged.max);
  }
}

struct Insertion {
  TreeSnapshot before, after;
  std::vector<RotationEvent> rotations;
};

// A sorted row then random boxes: rows make rotations happen.
std::vector<Insertion> rotatingInsertions() {
  DynamicAabbTree tree;
  tree.setRotationLogEnabled(true);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-20, 20);
  std::vector<Insertion> result;
  for (int i = 0; i < 120; ++i) {
    const Vec3 center = i < 60 ? Vec3(1.1 * i, 0, 0) : Vec3(coordinate(random), coordinate(random), coordinate(random));
    tree.clearRotationLog();
    tree.createProxy(Aabb::fromCenterHalfExtents(center, Vec3::Constant(0.5)), static_cast<std::uint32_t>(i));
    if (tree.rotationLog().empty()) continue;
    Insertion insertion;
    insertion.after = viewer::snapshotTree(tree);
    insertion.before = insertion.after;
    insertion.rotations = tree.rotationLog();
    viewer::undoRotations(insertion.before, insertion.rotations);
    result.push_back(std::move(insertion));
  }
  return result;
}

TEST(TreeView, SnapshotMatchesTheTreesOwnFigures) {
  DynamicAabbTree tree;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  for (int i = 0; i < 50; ++i)
    tree.createProxy(Aabb::fromCenterHalfExtents({coordinate(random), coordinate(random), 0}, Vec3::Constant(0.3)), 0);
  const TreeSnapshot snapshot = viewer::snapshotTree(tree);
  EXPECT_NEAR(snapshot.surfaceAreaRatio(), tree.surfaceAreaRatio(), 1e-12 * tree.surfaceAreaRatio());
  EXPECT_EQ(snapshot.height(), tree.height());
  EXPECT_EQ(leaves(snapshot).size(), 50u);
}

TEST(TreeView, UndoingRotationsGivesTheLargerUnrotatedTree) {
  const std::vector<Insertion> insertions = rotatingInsertions();
  ASSERT_GE(insertions.size(), 5u) << "the sorted row must make the tree rotate";
  for (const Insertion& insertion : insertions) {
    expectConsistent(insertion.before);
    EXPECT_EQ(leaves(insertion.before), leaves(insertion.after));
    // Each rotation only shrinks one box; the refit of the undone tree can only be as large or larger.
    double saved = 0;
    for (const RotationEvent& rotation : insertion.rotations) saved += rotation.areaBefore - rotation.areaAfter;
    EXPECT_GT(saved, 0);
    EXPECT_GT(internalArea(insertion.before), internalArea(insertion.after));
    // Redoing the swaps on the undone tree restores the rotated structure exactly.
    TreeSnapshot redone = insertion.before;
    for (const RotationEvent& rotation : insertion.rotations) {
      const int firstParent = redone.nodes[rotation.first].parent, secondParent = redone.nodes[rotation.second].parent;
      auto& a = redone.nodes[firstParent].child1 == rotation.first ? redone.nodes[firstParent].child1
                                                                   : redone.nodes[firstParent].child2;
      auto& b = redone.nodes[secondParent].child1 == rotation.second ? redone.nodes[secondParent].child1
                                                                     : redone.nodes[secondParent].child2;
      std::swap(a, b);
      redone.nodes[rotation.first].parent = secondParent;
      redone.nodes[rotation.second].parent = firstParent;
    }
    for (const int node : insertion.after.subtree(insertion.after.root)) {
      EXPECT_EQ(redone.nodes[node].child1, insertion.after.nodes[node].child1);
      EXPECT_EQ(redone.nodes[node].child2, insertion.after.nodes[node].child2);
    }
  }
}

TEST(TreeView, UndoRefusesEventsForOtherTrees) {
  DynamicAabbTree tree;
  tree.createProxy(Aabb::fromCenterHalfExtents(Vec3::Zero(), Vec3::Ones()), 0);
  TreeSnapshot snapshot = viewer::snapshotTree(tree);
  RotationEvent event;
  event.node = 0, event.first = 5, event.second = 9;
  EXPECT_THROW(viewer::undoRotations(snapshot, {event}), std::invalid_argument);
}

TEST(TreeView, DiagramShowsTheSwappedSubtreesInTheirColours) {
  const Insertion insertion = rotatingInsertions().front();
  viewer::TreeHighlight highlight;
  for (const RotationEvent& rotation : insertion.rotations) {
    highlight.movedDown.push_back(rotation.first);
    highlight.movedUp.push_back(rotation.second);
  }
  constexpr int width = 400, height = 300;
  render::Renderer renderer({width, height, 0});
  auto count = [&](const TreeSnapshot& tree, debugdraw::Color color) {
    debugdraw::Frame frame;
    viewer::drawTreeDiagram(tree, highlight, 0, 0, width, height, frame);
    const render::Image image = renderer.render(frame, viewer::pixelCamera(width, height));
    int matches = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const auto pixel = render::testing::pixelAt(image, x, y);
        matches += std::abs(pixel[0] - color.r * 255) < 40 && std::abs(pixel[1] - color.g * 255) < 40 &&
                   std::abs(pixel[2] - color.b * 255) < 40;
      }
    return matches;
  };
  EXPECT_GT(count(insertion.after, viewer::treecolors::movedDown), 20);
  EXPECT_GT(count(insertion.before, viewer::treecolors::movedUp), 20);
  viewer::TreeHighlight none;
  highlight = none;
  EXPECT_LT(count(insertion.after, viewer::treecolors::movedDown), 3);
}

}  // namespace
