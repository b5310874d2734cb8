// The `wire` layer draws each collider's true outline: every point of it on
// the collider's surface, hull edges exactly the edges of the merged faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <set>
#include <utility>

#include "engine/collider_outline.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/debug/world_debug_draw.h"
#include "engine/world.h"

namespace physdbg {
namespace {

namespace dd = debugdraw;

// The wire layer of a world holding one body.
dd::Frame wireOf(std::shared_ptr<const Collider> collider, const Vec3& position, const Quat& orientation) {
  World world;
  BodyDefinition definition;
  definition.collider = std::move(collider);
  definition.position = position;
  definition.orientation = orientation;
  world.addBody(definition);
  dd::Frame frame;
  emitDebugDraw(world, dd::parseLayers("wire"), frame);
  return frame;
}

const Quat tilted = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));

// Vertex index pairs (lower first) of the merged faces' edges, and how many
// times the outline has each.
std::set<std::pair<int, int>> faceEdges(const ConvexMeshCollider& hull) {
  std::set<std::pair<int, int>> edges;
  for (const HullFace& face : hull.hullFaces()) {
    for (std::size_t i = 0; i < face.vertices.size(); ++i) {
      const int a = face.vertices[i], b = face.vertices[(i + 1) % face.vertices.size()];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  }
  return edges;
}

int vertexIndex(const ConvexMeshCollider& hull, const Vec3& point) {
  const auto& vertices = hull.hullVertices();
  return static_cast<int>(std::find(vertices.begin(), vertices.end(), point) - vertices.begin());
}

// Each outline segment joins two hull vertices along a face edge, and each
// face edge is drawn exactly once.
void expectFaceEdgesOnce(const ConvexMeshCollider& hull) {
  std::multiset<std::pair<int, int>> drawn;
  for (const OutlineSegment& segment : localOutline(hull)) {
    const int a = vertexIndex(hull, segment.from), b = vertexIndex(hull, segment.to);
    drawn.insert({std::min(a, b), std::max(a, b)});
  }
  const std::set<std::pair<int, int>> expected = faceEdges(hull);
  EXPECT_EQ(drawn.size(), expected.size());
  const std::set<std::pair<int, int>> distinct(drawn.begin(), drawn.end());
  EXPECT_EQ(distinct, expected);
  // Euler's formula on the merged faces: E = V + F - 2.
  EXPECT_EQ(drawn.size(), hull.hullVertices().size() + hull.hullFaces().size() - 2);
}

std::vector<Vec3> cubeCorners(double half) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
  return corners;
}

TEST(ColliderOutline, SphereIsThreeGreatCirclesTurningWithTheBody) {
  const double radius = 0.7;
  const Vec3 centre(3, -1, 2);
  const dd::Frame frame = wireOf(std::make_shared<SphereCollider>(radius), centre, tilted);
  EXPECT_TRUE(frame.wireBoxes.empty());
  ASSERT_EQ(frame.lines.size(), 3u * outlineCircleSegments);
  // Each circle lies in a plane through the centre normal to one body axis.
  int inPlane[3] = {0, 0, 0};
  for (const dd::Line& line : frame.lines) {
    EXPECT_NEAR((line.from - centre).norm(), radius, 1e-12);
    EXPECT_NEAR((line.to - centre).norm(), radius, 1e-12);
    EXPECT_LT((line.to - line.from).norm(), radius * 0.2);  // short chords: it looks round
    for (int axis = 0; axis < 3; ++axis) {
      const Vec3 normal = tilted * Vec3::Unit(axis);
      if (std::abs(normal.dot(line.from - centre)) < 1e-12 && std::abs(normal.dot(line.to - centre)) < 1e-12)
        ++inPlane[axis];
    }
    EXPECT_FLOAT_EQ(line.color.r, 0.95f);
  }
  for (int count : inPlane) EXPECT_EQ(count, outlineCircleSegments);
}

TEST(ColliderOutline, CapsulePointsLieOnItsSurfaceAndReachBothTips) {
  const double radius = 0.3, halfHeight = 0.5;
  const Vec3 centre(-2, 1, 0.5);
  const dd::Frame frame = wireOf(std::make_shared<CapsuleCollider>(radius, halfHeight), centre, tilted);
  EXPECT_TRUE(frame.wireBoxes.empty());
  // Two end circles, four side lines, two half circles over each cap.
  EXPECT_EQ(frame.lines.size(), 2u * outlineCircleSegments + 4 + 4 * (outlineCircleSegments / 2));
  const Vec3 axis = tilted * Vec3::UnitY();
  const auto distanceToCore = [&](const Vec3& point) {
    const double along = std::clamp((point - centre).dot(axis), -halfHeight, halfHeight);
    return (point - centre - along * axis).norm();
  };
  int tips = 0;
  for (const dd::Line& line : frame.lines) {
    for (const Vec3& point : {line.from, line.to, Vec3(0.5 * (line.from + line.to))}) {
      // Chord midpoints sit a little inside the round parts, on the side lines.
      EXPECT_NEAR(distanceToCore(point), radius, radius * 0.01);
    }
    EXPECT_NEAR(distanceToCore(line.from), radius, 1e-12);
    for (const Vec3& tip : {Vec3(centre + axis * (halfHeight + radius)), Vec3(centre - axis * (halfHeight + radius))})
      tips += (line.from - tip).norm() < 1e-12 ? 1 : 0;
  }
  EXPECT_EQ(tips, 4);  // both cap arcs (two planes) pass through each tip
}

TEST(ColliderOutline, BoxIsItsTwelveEdges) {
  const Vec3 half(0.5, 1.0, 1.5);
  const BoxCollider box(half);
  const std::vector<OutlineSegment> outline = localOutline(box);
  ASSERT_EQ(outline.size(), 12u);
  int alongAxis[3] = {0, 0, 0};
  for (const OutlineSegment& edge : outline) {
    EXPECT_TRUE(edge.from.cwiseAbs().isApprox(half));  // corners
    EXPECT_TRUE(edge.to.cwiseAbs().isApprox(half));
    const Vec3 direction = (edge.to - edge.from).cwiseAbs();
    int axis = 0;
    direction.maxCoeff(&axis);
    EXPECT_NEAR(direction[axis], 2 * half[axis], 1e-12);
    EXPECT_NEAR(direction.sum(), direction[axis], 1e-12);  // parallel to the axis: an edge, not a diagonal
    ++alongAxis[axis];
  }
  for (int count : alongAxis) EXPECT_EQ(count, 4);

  const dd::Frame frame = wireOf(std::make_shared<BoxCollider>(half), Vec3(1, 2, 3), tilted);
  ASSERT_EQ(frame.wireBoxes.size(), 1u);  // the same twelve edges, drawn instanced
  EXPECT_TRUE(frame.lines.empty());
  EXPECT_TRUE(frame.wireBoxes[0].center.isApprox(Vec3(1, 2, 3)));
  EXPECT_TRUE(frame.wireBoxes[0].orientation.isApprox(tilted));
  EXPECT_TRUE(frame.wireBoxes[0].halfExtents.isApprox(half));
}

TEST(ColliderOutline, CubeHullHasTwelveEdgesAndNoFaceDiagonals) {
  std::vector<Vec3> points = cubeCorners(1.0);
  points.emplace_back(1, 0.3, -0.2);  // on a face: not a vertex
  const ConvexMeshCollider cube(points);
  ASSERT_EQ(cube.hullTriangles().size(), 12u);  // two per face, whose diagonals must not show
  const std::vector<OutlineSegment> outline = localOutline(cube);
  ASSERT_EQ(outline.size(), 12u);
  for (const OutlineSegment& edge : outline) EXPECT_NEAR((edge.to - edge.from).norm(), 2.0, 1e-12);
  expectFaceEdgesOnce(cube);
}

TEST(ColliderOutline, TetrahedronHullHasSixEdges) {
  const ConvexMeshCollider tetrahedron({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  EXPECT_EQ(localOutline(tetrahedron).size(), 6u);
  expectFaceEdgesOnce(tetrahedron);
}

// Random clouds, and a grid whose faces merge many triangles: the outline is
// always the merged faces' edges, each once.
TEST(ColliderOutline, HullOutlineIsTheMergedFacesEdgesEachOnce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int cloud = 0; cloud < 20; ++cloud) {
    std::vector<Vec3> points(4 + cloud * 5);
    for (Vec3& point : points) point = {coordinate(random), coordinate(random), coordinate(random)};
    expectFaceEdgesOnce(ConvexMeshCollider(points));
  }
  std::vector<Vec3> grid;
  for (int i = 0; i < 27; ++i) grid.emplace_back(i % 3, i / 3 % 3, i / 9);
  const ConvexMeshCollider gridHull(grid);
  EXPECT_EQ(localOutline(gridHull).size(), 12u);
  expectFaceEdgesOnce(gridHull);
}

TEST(ColliderOutline, HullBodyDrawsItsEdgesWhereItsSolidIs) {
  auto hull = std::make_shared<ConvexMeshCollider>(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
  World world;
  BodyDefinition definition;
  definition.collider = hull;
  definition.position = Vec3(5, 0, 0);
  definition.orientation = tilted;
  world.addBody(definition);
  dd::Frame frame;
  emitDebugDraw(world, dd::parseLayers("shapes,wire"), frame);
  ASSERT_EQ(frame.meshes.size(), 1u);
  EXPECT_TRUE(frame.wireBoxes.empty());
  ASSERT_EQ(frame.lines.size(), 6u);
  // Every line end is a vertex of the drawn solid mesh, placed the same way.
  const dd::SolidMesh& solid = frame.meshes[0];
  for (const dd::Line& line : frame.lines) {
    for (const Vec3& end : {line.from, line.to}) {
      const Vec3 local = solid.orientation.conjugate() * (end - solid.center);
      const bool onVertex = std::ranges::any_of(solid.mesh->vertices, [&](const Eigen::Vector3f& vertex) {
        return (vertex.cast<double>() - local).norm() < 1e-6;
      });
      EXPECT_TRUE(onVertex) << end.transpose();
    }
  }
}

}  // namespace
}  // namespace physdbg
