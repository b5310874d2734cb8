// The mesh debug layer: it outlines the triangles tested and marks the
// corrected edges when a body crosses seams, and emits nothing where no
// mesh is tested or the layer is not asked for.
#include <gtest/gtest.h>

#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"
#include "tests/engine/meshes/mesh_test_support.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

namespace dd = debugdraw;

bool sameColor(const dd::Color& a, const dd::Color& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

TEST(MeshLayer, OutlinesTestedTrianglesAndMarksCorrectedSeams) {
  WorldSettings settings;
  settings.threads = 1;
  World world(settings);
  world.addBody(meshtest::staticBody(meshtest::gridFloor(10, 2.0)));
  BodyDefinition box = testbodies::box(Vec3(-7.3, 0.5, 0.37));
  box.linearVelocity = Vec3(3, 0, 0.4);
  world.addBody(box);
  std::size_t tested = 0, corrected = 0, steps = 0;
  for (int step = 0; step < 90; ++step) {
    world.step();
    dd::Frame frame;
    dd::LayerCounts counts;
    emitDebugDraw(world, dd::parseLayers("mesh"), frame, &counts);
    EXPECT_EQ(counts.of(dd::Layer::Mesh), frame.primitiveCount());
    EXPECT_GE(frame.lines.size(), 3 * world.meshTests().size());
    for (const dd::Line& line : frame.lines) {
      EXPECT_EQ(line.tag.layer, static_cast<std::uint32_t>(dd::Layer::Mesh));
      corrected += sameColor(line.color, dd::colors::correctedEdge) ? 1 : 0;
    }
    for (const dd::Point& point : frame.points) corrected += sameColor(point.color, dd::colors::correctedEdge) ? 1 : 0;
    tested += world.meshTests().size();
    ++steps;
  }
  EXPECT_GE(tested, 2 * steps);  // a box over a grid meets two triangles or more
  EXPECT_GT(corrected, 0u);      // and its corners cross inactive seams
}

TEST(MeshLayer, EmitsNothingWithoutMeshesOrWhenNotAsked) {
  WorldSettings settings;
  settings.threads = 1;
  World boxes(settings);
  boxes.addBody(testbodies::floorSlab());
  boxes.addBody(testbodies::box(Vec3(0, 0.5, 0)));
  boxes.step();
  dd::Frame frame;
  emitDebugDraw(boxes, dd::parseLayers("mesh"), frame);
  EXPECT_EQ(frame.primitiveCount(), 0u);
  World level(settings);
  level.addBody(meshtest::staticBody(meshtest::gridFloor(4, 1.0)));
  level.addBody(testbodies::box(Vec3(0.2, 0.5, 0.1)));
  level.step();
  ASSERT_FALSE(level.meshTests().empty());
  dd::Frame other;
  dd::LayerCounts counts;
  emitDebugDraw(level, dd::parseLayers("shapes,contacts"), other, &counts);
  EXPECT_EQ(counts.of(dd::Layer::Mesh), 0u);
}

TEST(MeshLayer, TheTreeLayerDrawsEachMeshHierarchyByDepth) {
  WorldSettings settings;
  settings.threads = 1;
  World world(settings);
  const auto floor = meshtest::gridFloor(10, 2.0);
  BodyDefinition level = meshtest::staticBody(floor, Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX())));
  const BodyId id = world.addBody(level);
  dd::Frame frame;
  emitDebugDraw(world, dd::parseLayers("tree"), frame);
  std::size_t nodes = 0;
  int deepest = 0;
  for (const dd::WireBox& box : frame.wireBoxes) {
    if (box.tag.body != static_cast<int>(id)) continue;
    ++nodes;
    deepest = std::max(deepest, box.tag.depth);
    EXPECT_TRUE(box.orientation.isApprox(level.orientation));  // in the body's frame, turned with it
  }
  EXPECT_EQ(nodes, floor->bvh().nodes().size());
  EXPECT_EQ(deepest + 1, floor->bvh().depth());
}

}  // namespace
}  // namespace physdbg
