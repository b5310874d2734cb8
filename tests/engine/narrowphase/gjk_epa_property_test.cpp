#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "contact_test_helpers.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/convex_mesh_collider.h"

namespace physdbg {
namespace {

// A polytope in world space for the separating-axis reference: for two convex
// polytopes the minimum translation lies along a face normal of either or a
// cross product of an edge of each, so the smallest overlap over those axes
// is the exact penetration depth.
struct WorldPolytope {
  std::vector<Vec3> vertices;
  std::vector<Vec3> faceNormals;
  std::vector<Vec3> edgeDirections;
};

WorldPolytope boxPolytope(const Vec3& half, const Transform& t) {
  WorldPolytope p;
  for (int i = 0; i < 8; ++i) {
    p.vertices.push_back(t.apply(Vec3(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(), i & 4 ? half.z() : -half.z())));
  }
  const Mat3 r = t.rotation.toRotationMatrix();
  for (int axis = 0; axis < 3; ++axis) p.faceNormals.push_back(r.col(axis)), p.edgeDirections.push_back(r.col(axis));
  return p;
}

WorldPolytope meshPolytope(const ConvexMeshCollider& mesh, const Transform& t) {
  WorldPolytope p;
  for (const Vec3& v : mesh.hullVertices()) p.vertices.push_back(t.apply(v));
  for (const HullFace& f : mesh.hullFaces()) {
    p.faceNormals.push_back(t.rotation * f.normal);
    for (std::size_t i = 0; i < f.vertices.size(); ++i) {
      const Vec3 edge = mesh.hullVertices()[f.vertices[(i + 1) % f.vertices.size()]] - mesh.hullVertices()[f.vertices[i]];
      p.edgeDirections.push_back(t.rotation * edge.normalized());
    }
  }
  return p;
}

// Smallest overlap over all candidate axes: negative when separated.
double satMinimumOverlap(const WorldPolytope& a, const WorldPolytope& b) {
  std::vector<Vec3> axes = a.faceNormals;
  axes.insert(axes.end(), b.faceNormals.begin(), b.faceNormals.end());
  for (const Vec3& ea : a.edgeDirections) {
    for (const Vec3& eb : b.edgeDirections) {
      const Vec3 axis = ea.cross(eb);
      if (axis.norm() > 1e-6) axes.push_back(axis.normalized());
    }
  }
  double best = std::numeric_limits<double>::infinity();
  for (const Vec3& axis : axes) {
    double minA = 1e300, maxA = -1e300, minB = 1e300, maxB = -1e300;
    for (const Vec3& v : a.vertices) minA = std::min(minA, v.dot(axis)), maxA = std::max(maxA, v.dot(axis));
    for (const Vec3& v : b.vertices) minB = std::min(minB, v.dot(axis)), maxB = std::max(maxB, v.dot(axis));
    best = std::min(best, std::min(maxA - minB, maxB - minA));
  }
  return best;
}

WorldPolytope shifted(WorldPolytope p, const Vec3& offset) {
  for (Vec3& v : p.vertices) v += offset;
  return p;
}

// GJK's verdict against SAT, and EPA's depth as the minimum translation.
void checkPair(const WorldPolytope& pa, const WorldPolytope& pb, const ContactResult& r, int& penetrating) {
  testing::expectFinite(r);
  const double overlap = satMinimumOverlap(pa, pb);
  constexpr double band = 1e-6;  // touching tolerance
  if (overlap < -2 * band) {
    EXPECT_EQ(r.status, ContactStatus::Separated) << overlap;
    EXPECT_NEAR((r.pointB - r.pointA).norm(), r.distance, 1e-9);
    return;
  }
  if (overlap <= 2 * band) return;  // too close to call either way
  ASSERT_EQ(r.status, ContactStatus::Penetrating) << overlap;
  ++penetrating;
  EXPECT_NEAR(r.depth, overlap, 1e-9 * (1.0 + overlap));
  EXPECT_LE((r.pointA - r.pointB - r.depth * r.normal).norm(), 1e-9);
  constexpr double epsilon = 1e-7;
  EXPECT_LT(satMinimumOverlap(pa, shifted(pb, (r.depth + epsilon) * r.normal)), 0.0);
  EXPECT_GT(satMinimumOverlap(pa, shifted(pb, (r.depth - epsilon) * r.normal)), 0.0);
}

TEST(GjkEpaProperty, RandomBoxesAgreeWithSeparatingAxes) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> halfSize(0.1, 1.5), position(-2.0, 2.0);
  int penetrating = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 halfA(halfSize(rng), halfSize(rng), halfSize(rng)), halfB(halfSize(rng), halfSize(rng), halfSize(rng));
    const Transform ta{Vec3(position(rng), position(rng), position(rng)), testing::randomRotation(rng)};
    const Transform tb{Vec3(position(rng), position(rng), position(rng)), testing::randomRotation(rng)};
    SCOPED_TRACE(i);
    checkPair(boxPolytope(halfA, ta), boxPolytope(halfB, tb), collide(BoxCollider(halfA), ta, BoxCollider(halfB), tb),
              penetrating);
  }
  EXPECT_GT(penetrating, 500);  // the sample really exercises EPA
}

TEST(GjkEpaProperty, RandomHullsAgreeWithSeparatingAxes) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0), position(-1.5, 1.5);
  std::vector<std::unique_ptr<ConvexMeshCollider>> meshes;
  for (int m = 0; m < 12; ++m) {
    std::vector<Vec3> cloud;
    const int count = m % 2 == 0 ? 12 : 40;  // brute-force and hill-climbing supports
    for (int i = 0; i < count; ++i) cloud.emplace_back(coordinate(rng), 0.6 * coordinate(rng), coordinate(rng));
    meshes.push_back(std::make_unique<ConvexMeshCollider>(cloud));
  }
  int penetrating = 0;
  for (int i = 0; i < 600; ++i) {
    const ConvexMeshCollider& a = *meshes[i % meshes.size()];
    const ConvexMeshCollider& b = *meshes[(i * 7 + 3) % meshes.size()];
    const Transform ta{Vec3(position(rng), position(rng), position(rng)), testing::randomRotation(rng)};
    const Transform tb{Vec3(position(rng), position(rng), position(rng)), testing::randomRotation(rng)};
    SCOPED_TRACE(i);
    checkPair(meshPolytope(a, ta), meshPolytope(b, tb), collide(a, ta, b, tb), penetrating);
  }
  EXPECT_GT(penetrating, 100);
}

// Deep overlaps of round hulls make EPA's polytope large (a dozen or more
// expansions, faces seen in wide regions), where walking from face to face
// must find every face that has to go.
TEST(GjkEpaProperty, DeepOverlapsOfRoundHullsAgreeWithSeparatingAxes) {
  std::mt19937 rng(2026);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::uniform_real_distribution<double> position(-0.4, 0.4);
  std::vector<std::unique_ptr<ConvexMeshCollider>> meshes;
  for (int m = 0; m < 4; ++m) {
    std::vector<Vec3> cloud;
    for (int i = 0; i < 32; ++i) {
      cloud.push_back(Vec3(gaussian(rng), gaussian(rng), gaussian(rng)).normalized().cwiseProduct(Vec3(0.6, 0.5, 0.4)));
    }
    meshes.push_back(std::make_unique<ConvexMeshCollider>(cloud));
  }
  int penetrating = 0;
  for (int i = 0; i < 80; ++i) {
    const ConvexMeshCollider& a = *meshes[i % meshes.size()];
    const ConvexMeshCollider& b = *meshes[(i + 1 + i / 4) % meshes.size()];
    const Transform ta{Vec3::Zero(), testing::randomRotation(rng)};
    const Transform tb{Vec3(position(rng), position(rng), position(rng)), testing::randomRotation(rng)};
    SCOPED_TRACE(i);
    const ContactResult r = collide(a, ta, b, tb);
    checkPair(meshPolytope(a, ta), meshPolytope(b, tb), r, penetrating);
  }
  EXPECT_EQ(penetrating, 80);
}

}  // namespace
}  // namespace physdbg
