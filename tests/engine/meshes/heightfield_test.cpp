// Heightfields: the triangles a field makes are the triangles of the same
// grid built as a mesh, active edges included; queries find what brute
// force finds; bodies move on a flat field as on a box floor; 4 bytes a
// sample.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "engine/colliders/heightfield_collider.h"
#include "engine/world.h"
#include "tests/engine/meshes/mesh_test_support.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

HeightfieldCollider randomField(int columns, int rows, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> height(-0.4f, 0.4f);
  std::vector<float> heights(static_cast<std::size_t>(columns) * rows);
  for (float& h : heights) h = height(random);
  // Some flat patches and a ridge, so that inactive, convex and concave edges all occur.
  for (int i = 0; i < columns; ++i) heights[static_cast<std::size_t>(rows / 2) * columns + i] = 1.0f;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 4; ++i) heights[static_cast<std::size_t>(j) * columns + i] = 0.0f;
  return HeightfieldCollider(std::move(heights), columns, rows, 0.7, 0.4, 1.5);
}

TEST(Heightfield, MakesTheTrianglesAndActiveEdgesOfTheSameGridAsAMesh) {
  const HeightfieldCollider field = randomField(9, 7, 11);
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  field.sampledGrid(1000, vertices, triangles);
  ASSERT_EQ(triangles.size(), field.triangleCount());
  const TriangleMeshCollider mesh(vertices, triangles);
  ASSERT_EQ(mesh.triangles().size(), triangles.size());
  int active = 0, inactive = 0;
  for (std::uint32_t t = 0; t < field.triangleCount(); ++t) {
    const SourceTriangle fromField = field.triangleAt(t), fromMesh = mesh.triangleAt(t);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(fromField.corners[c], fromMesh.corners[c]) << t;
    EXPECT_LT((fromField.normal - fromMesh.normal).norm(), 1e-15) << t;
    EXPECT_EQ(fromField.activeEdges, fromMesh.activeEdges) << "triangle " << t;
    for (int e = 0; e < 3; ++e) (fromField.edgeActive(e) ? active : inactive) += 1;
  }
  EXPECT_GT(active, 0);
  EXPECT_GT(inactive, 0);
}

TEST(Heightfield, QueriesFindEveryTriangleBruteForceFinds) {
  const HeightfieldCollider field = randomField(40, 30, 5);
  std::mt19937 random(9);
  std::uniform_real_distribution<double> place(-16.0, 16.0), size(0.05, 3.0), up(-1.0, 1.5);
  std::vector<std::uint32_t> found;
  for (int query = 0; query < 300; ++query) {
    const Aabb box = Aabb::fromCenterHalfExtents(Vec3(place(random), up(random), place(random)),
                                                 Vec3(size(random), size(random), size(random)));
    found.clear();
    field.query(box, found);
    EXPECT_TRUE(std::is_sorted(found.begin(), found.end()));
    for (std::uint32_t t = 0; t < field.triangleCount(); ++t) {
      const SourceTriangle triangle = field.triangleAt(t);
      const Aabb bounds{triangle.corners[0].cwiseMin(triangle.corners[1]).cwiseMin(triangle.corners[2]),
                        triangle.corners[0].cwiseMax(triangle.corners[1]).cwiseMax(triangle.corners[2])};
      if (bounds.overlaps(box)) {
        EXPECT_TRUE(std::binary_search(found.begin(), found.end(), t)) << "query " << query << " triangle " << t;
      }
    }
  }
}

TEST(Heightfield, HoldsFourBytesASample) {
  const HeightfieldCollider field = randomField(300, 200, 1);
  EXPECT_EQ(field.sampleBytes(), 300u * 200u * 4u);
  EXPECT_LE(sizeof(HeightfieldCollider), 256u);
}

TEST(Heightfield, BadFieldsAreRefused) {
  EXPECT_THROW(HeightfieldCollider({0, 0, 0}, 3, 1, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(HeightfieldCollider({0, 0, 0, 0}, 2, 2, 0, 1, 1), std::invalid_argument);
  EXPECT_THROW(HeightfieldCollider({0, 0, 0}, 2, 2, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(HeightfieldCollider({0, NAN, 0, 0}, 2, 2, 1, 1, 1), std::invalid_argument);
}

TEST(Heightfield, BodiesMoveOnAFlatFieldAsOnABoxFloor) {
  // 21 x 21 samples a metre apart: the box floor's 20 m square.
  const auto field = std::make_shared<HeightfieldCollider>(std::vector<float>(21 * 21, 0.0f), 21, 21, 1.0, 1.0, 1.0);
  WorldSettings settings;
  settings.threads = 1;
  settings.allowSleep = false;
  for (const bool sphere : {false, true}) {
    BodyDefinition body = sphere ? testbodies::ball(Vec3(-6.2, 0.5, 0.3)) : testbodies::box(Vec3(-6.2, 0.5, 0.3));
    body.linearVelocity = Vec3(3, 0, 1);
    body.material.staticFriction = body.material.dynamicFriction = 0.1;
    World onField(settings), onBox(settings);
    BodyDefinition ground = meshtest::staticBody(field);
    ground.material = body.material;
    BodyDefinition slab = testbodies::floorSlab();
    slab.material = body.material;
    onField.addBody(ground);
    onBox.addBody(slab);
    const BodyId a = onField.addBody(body), b = onBox.addBody(body);
    double largest = 0.0;
    for (int step = 0; step < 150; ++step) {
      onField.step();
      onBox.step();
      largest = std::max({largest, (onField.body(a).position() - onBox.body(b).position()).norm(),
                          (onField.body(a).angularVelocity() - onBox.body(b).angularVelocity()).norm()});
    }
    EXPECT_GT(onField.body(a).position().x(), -2.0);  // across several cells
    EXPECT_LT(largest, 1e-8) << (sphere ? "sphere" : "box");
  }
}

}  // namespace
}  // namespace physdbg
