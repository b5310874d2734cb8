#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>

#include "render/sphere_detail.h"
#include "render/unit_meshes.h"

namespace physdbg::render {
namespace {

using Eigen::Vector3f;

Vector3f position(const MeshVertex& vertex) { return {vertex.position[0], vertex.position[1], vertex.position[2]}; }
Vector3f normal(const MeshVertex& vertex) { return {vertex.normal[0], vertex.normal[1], vertex.normal[2]}; }

// Closed, convex and counter-clockwise from outside: every face's winding
// normal points away from an interior point, and the signed
// volume from the divergence theorem matches the expected volume.
double checkOutwardAndVolume(const UnitMesh& mesh, const Vector3f& inside = Vector3f::Zero()) {
  double volume = 0;
  for (std::size_t first = 0; first < mesh.indices.size(); first += 3) {
    const Vector3f a = position(mesh.vertices[mesh.indices[first]]);
    const Vector3f b = position(mesh.vertices[mesh.indices[first + 1]]);
    const Vector3f c = position(mesh.vertices[mesh.indices[first + 2]]);
    const Vector3f winding = (b - a).cross(c - a);
    if (winding.norm() > 1e-9) {
      EXPECT_GT(winding.dot((a + b + c) / 3.0f - inside), 0) << "triangle " << first / 3;
    }
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

TEST(UnitMeshes, CubeIsClosedOutwardWithFaceNormals) {
  const UnitMesh cube = unitCube();
  EXPECT_EQ(cube.indices.size(), 36u);
  EXPECT_NEAR(checkOutwardAndVolume(cube), 8.0, 1e-5);
  for (const MeshVertex& vertex : cube.vertices) EXPECT_NEAR(normal(vertex).cwiseAbs().maxCoeff(), 1.0f, 0);
}

TEST(UnitMeshes, SphereVerticesLieOnTheUnitSphereWithRadialNormals) {
  const UnitMesh sphere = capsuleSphere(16, 8);
  const double volume = checkOutwardAndVolume(sphere);
  // An inscribed polyhedron of 16 x 8 cells: a little less than the ball.
  EXPECT_LT(volume, 4.0 / 3.0 * std::numbers::pi);
  EXPECT_GT(volume, 0.9 * 4.0 / 3.0 * std::numbers::pi);
  for (const MeshVertex& vertex : sphere.vertices) {
    EXPECT_NEAR(position(vertex).norm(), 1.0f, 1e-6f);
    EXPECT_NEAR((position(vertex) - normal(vertex)).norm(), 0.0f, 1e-6f);
    EXPECT_EQ(vertex.position[3], vertex.position[1] > 1e-6f ? 1.0f : vertex.position[1] < -1e-6f ? -1.0f
                                                                                                 : vertex.position[3]);
  }
  EXPECT_THROW(capsuleSphere(16, 7), std::invalid_argument);
}

TEST(UnitMeshes, ConeAndEdgesHaveTheExpectedShape) {
  const UnitMesh cone = unitCone(64);
  EXPECT_NEAR(checkOutwardAndVolume(cone, Vector3f(0, 0.25f, 0)), std::numbers::pi / 3.0, 0.01);  // pi r^2 h / 3
  const UnitMesh edges = unitCubeEdges();
  ASSERT_EQ(edges.indices.size(), 24u);
  for (std::size_t first = 0; first < edges.indices.size(); first += 2)  // each edge has length 2
    EXPECT_FLOAT_EQ((position(edges.vertices[edges.indices[first]]) - position(edges.vertices[edges.indices[first + 1]])).norm(), 2.0f);
}

// The cone shares its vertices; each face's normal rides on its first vertex
// (drawn with a flat normal and GL_FIRST_VERTEX_CONVENTION).
TEST(UnitMeshes, ConeFacesCarryTheirNormalOnTheirFirstVertex) {
  const UnitMesh cone = unitCone(16);
  EXPECT_EQ(cone.vertices.size(), 2u * 17u + 2u);
  ASSERT_EQ(cone.indices.size(), 16u * 2u * 3u);
  for (std::size_t first = 0; first < cone.indices.size(); first += 3) {
    const Vector3f a = position(cone.vertices[cone.indices[first]]);
    const Vector3f b = position(cone.vertices[cone.indices[first + 1]]);
    const Vector3f c = position(cone.vertices[cone.indices[first + 2]]);
    const Vector3f face = (b - a).cross(c - a).normalized();
    EXPECT_LT((normal(cone.vertices[cone.indices[first]]) - face).norm(), 1e-6f) << "triangle " << first / 3;
  }
}

TEST(UnitMeshes, FlatShadedMeshValidatesIndices) {
  debugdraw::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1};
  EXPECT_THROW(flatShadedMesh(mesh), std::invalid_argument);
  mesh.indices = {0, 1, 3};
  EXPECT_THROW(flatShadedMesh(mesh), std::invalid_argument);
  mesh.indices = {0, 1, 2};
  const UnitMesh flat = flatShadedMesh(mesh);
  ASSERT_EQ(flat.vertices.size(), 3u);
  for (const MeshVertex& vertex : flat.vertices) EXPECT_EQ(normal(vertex), Vector3f::UnitZ());
}

TEST(SphereDetail, CoarsestLevelWithinThreeQuartersOfAPixel) {
  int previous = 0;
  for (double radius = 0.5; radius < 5000; radius *= 1.3) {
    const int level = sphereDetailLevel(radius);
    EXPECT_GE(level, previous) << "radius " << radius;  // bigger spheres never get coarser
    previous = level;
    const double segments = kSphereSegments[level];
    if (level + 1 < static_cast<int>(kSphereSegments.size())) {
      EXPECT_LE(radius * (1 - std::cos(std::numbers::pi / segments)), 0.75) << "radius " << radius;
    }
    if (level > 0) {  // the next coarser level would have been too coarse
      EXPECT_GT(radius * (1 - std::cos(std::numbers::pi / kSphereSegments[level - 1])), 0.75) << "radius " << radius;
    }
  }
  EXPECT_EQ(sphereDetailLevel(1e9), static_cast<int>(kSphereSegments.size()) - 1);
}

// Orthographic, 10 m over 200 px: 20 px per metre.
TEST(ConeDetail, SmallHeadsAreCoarseInFrameOrderAndLargeOnesFine) {
  Camera camera;
  camera.orthographic = true;
  camera.orthoHeight = 10;
  std::vector<Instance> heads;
  for (double radius : {0.1, 0.5, 0.25, 0.31, 0.29, 2.0}) {  // 2, 10, 5, 6.2, 5.8 and 40 px
    Instance head{};
    head.scale[0] = static_cast<float>(radius);
    head.translation[0] = static_cast<float>(heads.size());  // its place in the frame
    heads.push_back(head);
  }
  const ConesByDetail split = splitConesByDetail(heads, camera, 200);
  auto places = [](const std::vector<Instance>& list) {
    std::vector<float> out;
    for (const Instance& head : list) out.push_back(head.translation[0]);
    return out;
  };
  EXPECT_EQ(places(split.coarse), (std::vector<float>{0, 2, 4}));
  EXPECT_EQ(places(split.fine), (std::vector<float>{1, 3, 5}));
  // The coarse cone's silhouette within half a pixel of a circle at the limit.
  EXPECT_LE(kCoarseConeRadiusPixels * (1 - std::cos(std::numbers::pi / kCoarseConeSegments)), 0.5);
}

}  // namespace
}  // namespace physdbg::render
