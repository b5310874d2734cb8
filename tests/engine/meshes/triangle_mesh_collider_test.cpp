// The mesh as built: validation, degenerate triangles, active edges and the
// hierarchy's queries against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "engine/colliders/triangle_mesh_collider.h"
#include "tests/engine/meshes/mesh_test_support.h"

namespace physdbg {
namespace {

TEST(TriangleMeshCollider, IndexPastTheVerticesIsRefusedNamingTheTriangle) {
  try {
    TriangleMeshCollider mesh({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}});
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("triangles[1]"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("vertex 3"), std::string::npos) << error.what();
  }
}

TEST(TriangleMeshCollider, NonFiniteVertexIsRefused) {
  EXPECT_THROW(TriangleMeshCollider({{0, 0, 0}, {1, NAN, 0}, {0, 0, 1}}, {{0, 2, 1}}), std::invalid_argument);
}

TEST(TriangleMeshCollider, DegenerateTrianglesAreDroppedAndCounted) {
  // A repeated corner, three corners in a line, and one good triangle.
  TriangleMeshCollider mesh({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {2, 0, 0}}, {{0, 0, 1}, {0, 1, 3}, {0, 2, 1}});
  EXPECT_EQ(mesh.droppedTriangles(), 2u);
  ASSERT_EQ(mesh.triangles().size(), 1u);
  EXPECT_TRUE(mesh.normal(0).isApprox(Vec3::UnitY()));
  EXPECT_THROW(TriangleMeshCollider({{0, 0, 0}, {1, 0, 0}}, {{0, 1, 1}}), std::invalid_argument);
}

TEST(TriangleMeshCollider, FlatGridHasOnlyItsBorderActive) {
  const auto grid = meshtest::gridFloor(6, 1.0);
  EXPECT_EQ(grid->triangles().size(), 72u);
  EXPECT_EQ(grid->activeEdgeCount(), 4u * 6u);  // the border; every inner edge is flat
}

// Two triangles facing up and sharing the edge (0,0,-1)-(0,0,1), the second
// turned down (a convex fold) or, for negative `degrees`, up (concave) about it.
TriangleMeshCollider fold(double degrees) {
  const double angle = degrees * M_PI / 180.0;
  return TriangleMeshCollider({{0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {std::cos(angle), -std::sin(angle), 0}},
                              {{0, 2, 1}, {0, 1, 3}}, 5.0);
}

TEST(TriangleMeshCollider, EdgeIsActiveOnlyWhereConvexBeyondTheThreshold) {
  const auto sharedActive = [](const TriangleMeshCollider& mesh) {
    EXPECT_EQ(mesh.edgeActive(0, 2), mesh.edgeActive(1, 0));  // both sides agree
    return mesh.edgeActive(0, 2);
  };
  EXPECT_EQ(fold(0.0).normal(0).y(), fold(0.0).normal(1).y());
  EXPECT_FALSE(sharedActive(fold(0.0)));    // flat
  EXPECT_FALSE(sharedActive(fold(4.0)));    // convex, under 5 degrees: smooth
  EXPECT_TRUE(sharedActive(fold(6.0)));     // convex, over 5 degrees: a real edge
  EXPECT_TRUE(sharedActive(fold(90.0)));    // a box's corner edge
  EXPECT_FALSE(sharedActive(fold(-30.0)));  // concave: each face's normal holds
  EXPECT_FALSE(sharedActive(fold(-90.0)));
}

TEST(TriangleMeshCollider, InconsistentWindingStillFindsTheFold) {
  // The second triangle of a 30 degree convex fold wound the other way.
  const double angle = 30.0 * M_PI / 180.0;
  TriangleMeshCollider mesh({{0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {std::cos(angle), -std::sin(angle), 0}},
                            {{0, 2, 1}, {1, 0, 3}});
  EXPECT_TRUE(mesh.edgeActive(0, 2));
  TriangleMeshCollider flat({{0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}}, {{0, 2, 1}, {1, 0, 3}});
  EXPECT_FALSE(flat.edgeActive(0, 2));
}

TEST(TriangleBvh, QueriesMatchBruteForceOnRandomTriangles) {
  std::mt19937 random(47);
  std::uniform_real_distribution<double> place(-20.0, 20.0), size(0.05, 2.0);
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  for (std::uint32_t t = 0; t < 3000; ++t) {
    const Vec3 centre(place(random), place(random), place(random));
    for (int c = 0; c < 3; ++c) vertices.push_back(centre + size(random) * Vec3::Random());
    triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  const TriangleMeshCollider mesh(vertices, triangles);
  const TriangleBvh& bvh = mesh.bvh();
  for (const TriangleBvh::Node& node : bvh.nodes()) {
    if (node.isLeaf()) {
      EXPECT_LE(node.count, static_cast<std::uint32_t>(TriangleBvh::maxLeafTriangles));
    }
  }
  EXPECT_LT(bvh.depth(), 30);
  std::vector<std::uint32_t> found;
  for (int query = 0; query < 200; ++query) {
    const Vec3 centre(place(random), place(random), place(random));
    const Aabb box = Aabb::fromCenterHalfExtents(centre, Vec3::Constant(size(random) * 2));
    found.clear();
    mesh.query(box, found);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t t = 0; t < mesh.triangles().size(); ++t) {
      const MeshTriangle& triangle = mesh.triangles()[t];
      const Vec3 &a = mesh.vertices()[triangle[0]], &b = mesh.vertices()[triangle[1]], &c = mesh.vertices()[triangle[2]];
      if (Aabb{a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c)}.overlaps(box)) expected.push_back(t);
    }
    EXPECT_EQ(found, expected);
  }
}

TEST(TriangleBvh, CoincidentTrianglesStillMakeSmallLeavesAndAShallowTree) {
  // 10,000 copies of one triangle: no split by position exists.
  std::vector<MeshTriangle> triangles(10000, MeshTriangle{0, 1, 2});
  const TriangleMeshCollider mesh({{0, 0, 0}, {0, 0, 1}, {1, 0, 0}}, triangles);
  for (const TriangleBvh::Node& node : mesh.bvh().nodes()) {
    if (node.isLeaf()) {
      EXPECT_LE(node.count, static_cast<std::uint32_t>(TriangleBvh::maxLeafTriangles));
    }
  }
  EXPECT_LT(mesh.bvh().depth(), 64);
  std::vector<std::uint32_t> found;
  mesh.query(Aabb{Vec3(0.2, -0.1, 0.2), Vec3(0.3, 0.1, 0.3)}, found);
  EXPECT_EQ(found.size(), 10000u);
}

TEST(TriangleBvh, ExponentiallySpacedTrianglesStayShallow) {
  // Centres at 2^k: the heuristic would peel one off a level; past its
  // depth the median split bounds the tree.
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  for (std::uint32_t k = 0; k < 1000; ++k) {
    const double x = std::pow(1.07, k);
    vertices.insert(vertices.end(), {{x, 0, 0}, {x, 0, 1e-3 * x}, {x + 1e-3 * x, 0, 0}});
    triangles.push_back({3 * k, 3 * k + 1, 3 * k + 2});
  }
  const TriangleMeshCollider mesh(vertices, triangles);
  EXPECT_LT(mesh.bvh().depth(), 80);
}

}  // namespace
}  // namespace physdbg
