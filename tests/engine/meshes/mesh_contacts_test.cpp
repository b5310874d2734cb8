// Contacts of each convex shape against a mesh's triangles, in the face,
// edge and corner regions of one triangle, with the mesh turned and moved
// so that no answer holds by accident of axes: depths and normals against
// the geometry worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/narrowphase/mesh_contacts.h"
#include "tests/engine/meshes/mesh_test_support.h"

namespace physdbg {
namespace {

constexpr double exact = 1e-9;  // GJK/EPA converge to 1e-12 of the pair's size

// One triangle in the plane y = 0 of its frame, corners (0,0,0), (0,0,4),
// (4,0,0), facing +y, and the pose that turns and moves it somewhere else.
struct OneTriangle {
  std::shared_ptr<TriangleMeshCollider> mesh = std::make_shared<TriangleMeshCollider>(
      std::vector<Vec3>{{0, 0, 0}, {0, 0, 4}, {4, 0, 0}}, std::vector<MeshTriangle>{{0, 1, 2}});
  Transform pose{Vec3(3, -2, 5), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))};
  Vec3 world(const Vec3& local) const { return pose.apply(local); }
  Vec3 direction(const Vec3& local) const { return pose.rotation * local; }
};

double signedDistance(const ContactResult& result) {
  return result.status == ContactStatus::Separated ? result.distance : -result.depth;
}

// What collideWithMesh gives one pair (bodies 0 and 1), reach 5 cm.
struct MeshAnswer {
  ContactResult deepest;
  std::vector<ContactManifold> manifolds;
  MeshContactCounts counts;
};

MeshAnswer meshContacts(const TriangleMeshCollider& mesh, const Transform& meshPose, const Collider& convex,
                        const Transform& at, bool meshIsA = true) {
  MeshAnswer answer;
  MeshContactScratch scratch;
  answer.deepest = collideWithMesh(mesh, meshPose, convex, at, meshIsA, 0, 1, 0.05, NarrowPhaseOptions{}, scratch,
                                   answer.manifolds, answer.counts);
  return answer;
}

TEST(MeshContacts, SphereOverTheFace) {
  const OneTriangle triangle;
  SphereCollider sphere(0.5);
  const Transform at{triangle.world(Vec3(1, 0.4, 1)), Quat::Identity()};
  const ContactResult result =
      collideWithTriangle(triangle.mesh->triangleAt(0), triangle.pose, sphere, at, NarrowPhaseOptions{}, 1.0);
  EXPECT_NEAR(signedDistance(result), -0.1, exact);
  EXPECT_LT((result.normal - triangle.direction(Vec3::UnitY())).norm(), exact);
  EXPECT_LT((result.pointA - triangle.world(Vec3(1, 0, 1))).norm(), exact);
}

TEST(MeshContacts, SphereBesideABorderEdgeTakesTheEdgesNormal) {
  // Beyond the edge x = 0 (a border, so active) by 0.3, 0.3 above the plane.
  const OneTriangle triangle;
  SphereCollider sphere(0.5);
  const Transform at{triangle.world(Vec3(-0.3, 0.3, 2)), Quat::Identity()};
  CorrectedFeature corrected = CorrectedFeature::Face;
  const ContactResult result =
      collideWithTriangle(triangle.mesh->triangleAt(0), triangle.pose, sphere, at, NarrowPhaseOptions{}, 1.0, &corrected);
  EXPECT_EQ(corrected, CorrectedFeature::None);
  EXPECT_NEAR(signedDistance(result), std::sqrt(0.18) - 0.5, exact);
  EXPECT_LT((result.normal - triangle.direction(Vec3(-1, 1, 0).normalized())).norm(), exact);
  EXPECT_LT((result.pointA - triangle.world(Vec3(0, 0, 2))).norm(), exact);
}

TEST(MeshContacts, SphereBeyondACornerTakesTheCornersNormal) {
  const OneTriangle triangle;
  SphereCollider sphere(1.0);
  const Vec3 offset(0.3, 0.3, -0.2);  // from corner (4, 0, 0), in its region past both edges
  const Transform at{triangle.world(Vec3(4, 0, 0) + offset), Quat::Identity()};
  const ContactResult result =
      collideWithTriangle(triangle.mesh->triangleAt(0), triangle.pose, sphere, at, NarrowPhaseOptions{}, 1.0);
  EXPECT_NEAR(signedDistance(result), offset.norm() - 1.0, exact);
  EXPECT_LT((result.normal - triangle.direction(offset.normalized())).norm(), exact);
}

TEST(MeshContacts, BoxOnTheFaceGetsFourPointsAtItsDepth) {
  const OneTriangle triangle;
  BoxCollider box(Vec3(0.3, 0.2, 0.25));
  // Turned about the face normal, sunk 0.01 into the face, well inside it.
  const Transform at{triangle.world(Vec3(1.2, 0.19, 1.1)),
                     triangle.pose.rotation * Quat(Eigen::AngleAxisd(0.4, Vec3::UnitY()))};
  const MeshAnswer answer = meshContacts(*triangle.mesh, triangle.pose, box, at);
  EXPECT_NEAR(signedDistance(answer.deepest), -0.01, exact);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_EQ(answer.manifolds[0].pointCount, 4);
  EXPECT_LT((answer.manifolds[0].normal - triangle.direction(Vec3::UnitY())).norm(), exact);
  for (int p = 0; p < answer.manifolds[0].pointCount; ++p) EXPECT_NEAR(answer.manifolds[0].points[p].separation, -0.01, exact);
  EXPECT_EQ(answer.counts.triangles, 1);
}

TEST(MeshContacts, BoxHangingOverABorderEdgeKeepsOnlyThePartOnTheFace) {
  // Half over the edge x = 0: the two corners over the face, and the points
  // where the box's edges cross the triangle's, carry it.
  const OneTriangle triangle;
  BoxCollider box(Vec3(0.5, 0.5, 0.5));
  const Transform at{triangle.world(Vec3(0.0, 0.49, 2.0)), triangle.pose.rotation};
  const MeshAnswer answer = meshContacts(*triangle.mesh, triangle.pose, box, at);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_LT((answer.manifolds[0].normal - triangle.direction(Vec3::UnitY())).norm(), exact);
  ASSERT_EQ(answer.manifolds[0].pointCount, 4);
  for (int p = 0; p < answer.manifolds[0].pointCount; ++p) {
    const Vec3 local = triangle.pose.applyInverse(answer.manifolds[0].points[p].pointA);
    EXPECT_GE(local.x(), -2e-6);  // on the triangle's side of its border, within clipTolerance
    EXPECT_NEAR(answer.manifolds[0].points[p].separation, -0.01, exact);
  }
}

TEST(MeshContacts, CapsuleLyingOnTheFaceGetsBothEnds) {
  const OneTriangle triangle;
  CapsuleCollider capsule(0.2, 0.5);  // axis along its local y
  const Transform at{triangle.world(Vec3(1.5, 0.19, 1.5)),
                     triangle.pose.rotation * Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()))};
  const MeshAnswer answer = meshContacts(*triangle.mesh, triangle.pose, capsule, at);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_EQ(answer.manifolds[0].pointCount, 2);
  for (int p = 0; p < answer.manifolds[0].pointCount; ++p) EXPECT_NEAR(answer.manifolds[0].points[p].separation, -0.01, exact);
}

TEST(MeshContacts, HullOnTheFaceAtItsDepth) {
  const OneTriangle triangle;
  // A tetrahedron standing on its base (y = 0 in its frame) with its apex up.
  ConvexMeshCollider hull({{-0.3, 0, -0.3}, {0.3, 0, -0.3}, {0, 0, 0.3}, {0, 0.5, 0}});
  const Transform at{triangle.world(Vec3(1.5, -0.02, 1.2)), triangle.pose.rotation};
  const MeshAnswer answer = meshContacts(*triangle.mesh, triangle.pose, hull, at);
  EXPECT_NEAR(signedDistance(answer.deepest), -0.02, exact);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_EQ(answer.manifolds[0].pointCount, 3);
}

TEST(MeshContacts, MeshAsBodyBFlipsTheNormal) {
  const OneTriangle triangle;
  SphereCollider sphere(0.5);
  const Transform at{triangle.world(Vec3(1, 0.4, 1)), Quat::Identity()};
  const MeshAnswer answer = meshContacts(*triangle.mesh, triangle.pose, sphere, at, false);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_LT((answer.manifolds[0].normal + triangle.direction(Vec3::UnitY())).norm(), exact);  // from the sphere (a) to the mesh
  EXPECT_NEAR(answer.manifolds[0].points[0].separation, -0.1, exact);
}

TEST(MeshContacts, SphereOnAnInnerCornerOfAFlatGridIsOnePointAlongTheFaceNormal) {
  // Six triangles meet at the grid's vertex (0, 0, 0), and every edge there
  // is flat: whichever triangle finds the sphere, the answer is the face's.
  const auto grid = meshtest::gridFloor(4, 1.0);
  SphereCollider sphere(0.5);
  const Transform at{Vec3(0, 0.45, 0), Quat::Identity()};
  const MeshAnswer answer = meshContacts(*grid, Transform{}, sphere, at);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  ASSERT_EQ(answer.manifolds[0].pointCount, 1);
  EXPECT_LT((answer.manifolds[0].normal - Vec3::UnitY()).norm(), exact);
  EXPECT_NEAR(answer.manifolds[0].points[0].separation, -0.05, exact);
  EXPECT_GE(answer.counts.triangles, 6);
}

TEST(MeshContacts, BoxSunkAcrossASeamIsPushedUpNotSideways) {
  // A box sunk 0.2 into a flat grid, straddling an inner edge by 0.05: EPA
  // on the triangle it barely reaches says "out sideways, 0.05"; the edge is
  // flat, so the face normal and the full 0.2 are what hold.
  const auto grid = meshtest::gridFloor(4, 1.0);
  BoxCollider box(Vec3(0.5, 0.5, 0.5));
  const Transform at{Vec3(-0.45, 0.3, -0.5), Quat::Identity()};
  const MeshAnswer answer = meshContacts(*grid, Transform{}, box, at);
  ASSERT_EQ(answer.manifolds.size(), 1u);
  EXPECT_LT((answer.manifolds[0].normal - Vec3::UnitY()).norm(), exact);
  EXPECT_EQ(answer.manifolds[0].pointCount, 4);
  for (int p = 0; p < answer.manifolds[0].pointCount; ++p) EXPECT_NEAR(answer.manifolds[0].points[p].separation, -0.2, exact);
  EXPECT_NEAR(signedDistance(answer.deepest), -0.2, exact);
  EXPECT_GT(answer.counts.corrected, 0);
}

}  // namespace
}  // namespace physdbg
