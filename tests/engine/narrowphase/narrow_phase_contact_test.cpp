#include <gtest/gtest.h>

#include <cmath>

#include "contact_test_helpers.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {
namespace {

using testing::compose;
using testing::expectFinite;
using testing::expectSameUnderMotion;
using testing::gjkEpaOnly;
using testing::testMotions;

constexpr double kTight = 1e-9;  // relative to unit-sized shapes

NarrowPhaseOptions generalOnly() {
  NarrowPhaseOptions options;
  options.analyticFastPaths = false;
  return options;
}

Transform at(double x, double y, double z) { return {Vec3(x, y, z), Quat::Identity()}; }

// Runs the pair under every test motion, with and without fast paths, and
// compares with the untransformed answer.
void expectInvariant(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                     const ContactResult& expected, bool comparePoints = true) {
  for (const Transform& motion : testMotions(7)) {
    for (bool fast : {true, false}) {
      NarrowPhaseOptions options;
      options.analyticFastPaths = fast;
      SCOPED_TRACE(::testing::Message() << "offset " << motion.position.transpose() << " fast " << fast);
      const ContactResult moved = collide(a, compose(motion, ta), b, compose(motion, tb), options);
      expectSameUnderMotion(expected, moved, motion, kTight, comparePoints);
    }
  }
}

TEST(NarrowPhaseContact, SpheresOneAndAHalfApart) {
  SphereCollider unit(1.0);
  const ContactResult r = collide(unit, at(0, 0, 0), unit, at(1.5, 0, 0));
  EXPECT_EQ(r.status, ContactStatus::Penetrating);
  EXPECT_NEAR(r.depth, 0.5, 1e-15);
  EXPECT_LE((r.normal - Vec3::UnitX()).norm(), 1e-15);
  EXPECT_LE((r.pointA - Vec3(1, 0, 0)).norm(), 1e-15);
  EXPECT_LE((r.pointB - Vec3(0.5, 0, 0)).norm(), 1e-15);
  EXPECT_FALSE(r.usedGeneralPath);
  expectInvariant(unit, at(0, 0, 0), unit, at(1.5, 0, 0), r);
}

TEST(NarrowPhaseContact, CoincidentSpheresHaveAFiniteNormalAndFullDepth) {
  SphereCollider a(1.0), b(0.5);
  for (bool fast : {true, false}) {
    NarrowPhaseOptions options;
    options.analyticFastPaths = fast;
    const ContactResult r = collide(a, at(3, 4, 5), b, at(3, 4, 5), options);
    expectFinite(r);
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, 1.5, 1e-12);
  }
}

TEST(NarrowPhaseContact, SeparatedSpheresReportDistance) {
  SphereCollider unit(1.0);
  const ContactResult r = collide(unit, at(0, 0, 0), unit, at(0, 3, 0));
  EXPECT_EQ(r.status, ContactStatus::Separated);
  EXPECT_NEAR(r.distance, 1.0, 1e-15);
  EXPECT_EQ(r.depth, 0.0);
  expectInvariant(unit, at(0, 0, 0), unit, at(0, 3, 0), r);
}

struct BoxSphereCase {
  const char* name;
  Vec3 centre;
  double depth;
  Vec3 normal;
  Vec3 boxPoint;
};

TEST(NarrowPhaseContact, BoxSphereFaceEdgeAndVertex) {
  BoxCollider box(Vec3(1, 1, 1));
  SphereCollider sphere(0.5);
  const double edgeGap = 0.2 * std::sqrt(2.0), vertexGap = 0.2 * std::sqrt(3.0);
  const BoxSphereCase cases[] = {
      {"face", Vec3(0, 0, 1.3), 0.2, Vec3::UnitZ(), Vec3(0, 0, 1)},
      {"edge", Vec3(1.2, 1.2, 0), 0.5 - edgeGap, Vec3(1, 1, 0).normalized(), Vec3(1, 1, 0)},
      {"vertex", Vec3(1.2, 1.2, 1.2), 0.5 - vertexGap, Vec3(1, 1, 1).normalized(), Vec3(1, 1, 1)},
      {"centre inside", Vec3(0.9, 0.1, 0.0), 0.6, Vec3::UnitX(), Vec3(1, 0.1, 0)},
  };
  for (const BoxSphereCase& c : cases) {
    SCOPED_TRACE(c.name);
    const ContactResult r = collide(box, Transform{}, sphere, at(c.centre.x(), c.centre.y(), c.centre.z()));
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, c.depth, 1e-15);
    EXPECT_LE((r.normal - c.normal).norm(), 1e-15);
    EXPECT_LE((r.pointA - c.boxPoint).norm(), 1e-15);
    EXPECT_LE((r.pointB - (c.centre - 0.5 * c.normal)).norm(), 1e-15);
    const ContactResult flipped = collide(sphere, at(c.centre.x(), c.centre.y(), c.centre.z()), box, Transform{});
    EXPECT_NEAR(flipped.depth, c.depth, 1e-15);
    EXPECT_LE((flipped.normal + c.normal).norm(), 1e-15);
    expectInvariant(box, Transform{}, sphere, at(c.centre.x(), c.centre.y(), c.centre.z()), r);
  }
}

TEST(NarrowPhaseContact, CubesOnePointNineApart) {
  BoxCollider cube(Vec3(1, 1, 1));
  const ContactResult r = collide(cube, at(0, 0, 0), cube, at(0, 0, 1.9), gjkEpaOnly());
  expectFinite(r);
  EXPECT_EQ(r.status, ContactStatus::Penetrating);
  EXPECT_NEAR(r.depth, 0.1, kTight);
  EXPECT_LE((r.normal - Vec3::UnitZ()).norm(), kTight);
  EXPECT_NEAR(r.pointA.z(), 1.0, kTight);
  EXPECT_NEAR(r.pointB.z(), 0.9, kTight);
  EXPECT_TRUE(r.usedGeneralPath);
  EXPECT_GT(r.epaIterations, 0);
  // The face contact has no unique point: compare points up to that freedom.
  expectInvariant(cube, at(0, 0, 0), cube, at(0, 0, 1.9), r, false);
}

TEST(NarrowPhaseContact, IdenticalBoxesAtTheSamePose) {
  BoxCollider box(Vec3(1, 0.5, 0.25));
  for (const Transform& motion : testMotions(11)) {
    const ContactResult r = collide(box, motion, box, motion);
    expectFinite(r);
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, 0.5, kTight);  // out through the thinnest axis
    EXPECT_NEAR(std::abs(r.normal.dot(motion.rotation * Vec3::UnitZ())), 1.0, kTight);
  }
}

TEST(NarrowPhaseContact, ThinPlateAgainstSphere) {
  BoxCollider plate(Vec3(1, 1, 0.005));
  SphereCollider sphere(0.5);
  const ContactResult r = collide(plate, Transform{}, sphere, at(0.2, -0.3, 0.497));
  EXPECT_EQ(r.status, ContactStatus::Penetrating);
  EXPECT_NEAR(r.depth, 0.008, 1e-15);
  EXPECT_LE((r.normal - Vec3::UnitZ()).norm(), 1e-15);
  expectInvariant(plate, Transform{}, sphere, at(0.2, -0.3, 0.497), r);
  // Sphere centre inside the plate: out through the nearer face.
  const ContactResult inside = collide(plate, Transform{}, sphere, at(0, 0, -0.001), generalOnly());
  EXPECT_NEAR(inside.depth, 0.5 + 0.004, kTight);
  EXPECT_LE((inside.normal + Vec3::UnitZ()).norm(), kTight);
}

TEST(NarrowPhaseContact, ConvexMeshCubeMatchesTheBox) {
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  points.emplace_back(0.2, 0.1, -0.3);  // interior point and a face point
  points.emplace_back(1.0, 0.5, 0.0);
  ConvexMeshCollider meshCube(points);
  BoxCollider box(Vec3(1, 1, 1));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Transform ta{Vec3(unit(rng), unit(rng), unit(rng)), testing::randomRotation(rng)};
    const Transform tb{Vec3(unit(rng), unit(rng), unit(rng)) * 2.5, testing::randomRotation(rng)};
    const ContactResult expected = collide(box, ta, box, tb);
    const ContactResult mesh = collide(meshCube, ta, box, tb);
    expectFinite(mesh);
    ASSERT_EQ(expected.status, mesh.status);
    EXPECT_NEAR(expected.depth, mesh.depth, kTight);
    EXPECT_NEAR(expected.distance, mesh.distance, kTight);
    EXPECT_LE((expected.normal - mesh.normal).norm(), 1e-7);  // normals of near-ties are less well conditioned
  }
}

TEST(NarrowPhaseContact, TouchingShapesGiveNoNanAndNoDeepContact) {
  BoxCollider cube(Vec3(1, 1, 1));
  SphereCollider sphere(1.0);
  struct Pair {
    const Collider* a;
    const Collider* b;
    Transform tb;
  };
  const Pair pairs[] = {
      {&cube, &cube, at(0, 0, 2)},                                   // face on face
      {&cube, &cube, at(2, 2, 0)},                                   // edge on edge
      {&cube, &cube, at(2, 2, 2)},                                   // vertex on vertex
      {&cube, &cube, at(2, 0.5, 0.3)},                               // offset faces
      {&cube, &sphere, at(0, 0, 2)},                                 // sphere on face
      {&sphere, &sphere, at(2, 0, 0)},                               // spheres
      {&cube, &cube, {Vec3(0, 0, 1 + std::sqrt(2.0)), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()))}},  // edge on face
  };
  for (const Pair& p : pairs) {
    for (const Transform& motion : testMotions(5)) {
      for (bool fast : {true, false}) {
        NarrowPhaseOptions options;
        options.analyticFastPaths = fast;
        const ContactResult r = collide(*p.a, motion, *p.b, compose(motion, p.tb), options);
        expectFinite(r);
        EXPECT_EQ(r.status, ContactStatus::Touching) << "offset " << motion.position.norm();
        EXPECT_EQ(r.depth, 0.0);
        EXPECT_EQ(r.distance, 0.0);
      }
    }
  }
}

TEST(NarrowPhaseContact, FastPathsAgreeWithTheGeneralPath) {
  BoxCollider box(Vec3(0.7, 0.3, 1.1));
  SphereCollider sphere(0.4);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.6, 1.6);
  for (int i = 0; i < 2000; ++i) {
    const Transform tb{Vec3(unit(rng), unit(rng), unit(rng)), Quat::Identity()};
    const Transform ta{Vec3::Zero(), testing::randomRotation(rng)};
    const ContactResult fast = collide(box, ta, sphere, tb);
    const ContactResult general = collide(box, ta, sphere, tb, generalOnly());
    ASSERT_EQ(fast.status, general.status) << i;
    EXPECT_NEAR(fast.depth, general.depth, kTight);
    EXPECT_NEAR(fast.distance, general.distance, kTight);
    EXPECT_LE((fast.normal - general.normal).norm(), 1e-7) << i;
    EXPECT_LE((fast.pointB - general.pointB).norm(), 1e-7) << i;
  }
}

TEST(NarrowPhaseContact, BadInputThrows) {
  SphereCollider sphere(1.0);
  Transform bad{Vec3(NAN, 0, 0), Quat::Identity()};
  EXPECT_THROW(collide(sphere, bad, sphere, Transform{}), std::invalid_argument);
  NarrowPhaseOptions options;
  options.maxGjkIterations = 0;
  EXPECT_THROW(collide(sphere, Transform{}, sphere, Transform{}, options), std::invalid_argument);
  options = {};
  options.touchingTolerance = -1.0;
  EXPECT_THROW(collide(sphere, Transform{}, sphere, Transform{}, options), std::invalid_argument);
}

TEST(NarrowPhaseContact, CountersTallyPaths) {
  SphereCollider sphere(1.0);
  BoxCollider box(Vec3(1, 1, 1));
  NarrowPhaseCounters counters;
  counters.add(collide(sphere, Transform{}, sphere, at(1, 0, 0)));
  counters.add(collide(box, Transform{}, box, at(1, 0, 0), gjkEpaOnly()));
  counters.add(collide(box, Transform{}, box, at(5, 0, 0), gjkEpaOnly()));
  EXPECT_EQ(counters.pairs, 3);
  EXPECT_EQ(counters.fastPath, 1);
  EXPECT_EQ(counters.gjk, 2);
  EXPECT_EQ(counters.epa, 1);
}

}  // namespace
}  // namespace physdbg

namespace physdbg {
namespace {

TEST(NarrowPhaseContact, BoxOnAThinPlateUnderMotions) {
  BoxCollider plate(Vec3(2, 2, 0.005));
  BoxCollider box(Vec3(0.5, 0.3, 0.2));
  const Transform onPlate{Vec3(0.4, -0.2, 0.005 + 0.2 - 0.003), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))};
  const ContactResult r = collide(plate, Transform{}, box, onPlate);
  EXPECT_EQ(r.status, ContactStatus::Penetrating);
  EXPECT_NEAR(r.depth, 0.003, 1e-12);
  EXPECT_LE((r.normal - Vec3::UnitZ()).norm(), 1e-12);
  for (const Transform& motion : testing::testMotions(13)) {
    const ContactResult moved = collide(plate, motion, box, testing::compose(motion, onPlate));
    testing::expectSameUnderMotion(r, moved, motion, 1e-9, false);
  }
}

TEST(NarrowPhaseContact, SpentBudgetsStillGiveFiniteBoundedAnswers) {
  BoxCollider a(Vec3(1, 0.7, 0.4)), b(Vec3(0.6, 0.5, 0.9));
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> unit(-0.8, 0.8);
  for (int i = 0; i < 200; ++i) {
    const Transform ta{Vec3::Zero(), testing::randomRotation(rng)};
    const Transform tb{Vec3(unit(rng), unit(rng), unit(rng)), testing::randomRotation(rng)};
    const ContactResult exact = collide(a, ta, b, tb);
    NarrowPhaseOptions tight;
    tight.maxEpaFaces = 6;
    tight.maxGjkIterations = 3;
    const ContactResult bounded = collide(a, ta, b, tb, tight);
    testing::expectFinite(bounded);
    if (bounded.status == ContactStatus::Penetrating) {
      EXPECT_LE(bounded.depth, exact.depth + 1e-9);
    }
  }
}

}  // namespace
}  // namespace physdbg
