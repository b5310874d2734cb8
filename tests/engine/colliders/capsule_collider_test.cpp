#include <gtest/gtest.h>

#include <numbers>

#include "tests/engine/narrowphase/contact_test_helpers.h"
#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {
namespace {

Transform at(double x, double y, double z) { return {Vec3(x, y, z), Quat::Identity()}; }

TEST(CapsuleCollider, SupportBoundsAndMass) {
  CapsuleCollider capsule(0.5, 1.0);
  EXPECT_LE((capsule.localSupport(Vec3(0, 2, 0)) - Vec3(0, 1.5, 0)).norm(), 1e-15);
  EXPECT_LE((capsule.localSupport(Vec3(3, -4, 0)) - Vec3(0.3, -1.4, 0)).norm(), 1e-15);
  EXPECT_NEAR(capsule.localBounds().max.y(), 1.5, 0.0);
  EXPECT_NEAR(capsule.volume(), std::numbers::pi * 0.25 * (2.0 + 4.0 / 3.0 * 0.5), 1e-14);
  // Zero height is a sphere: 2/5 r^2 about every axis.
  CapsuleCollider ball(0.5, 0.0);
  EXPECT_LE((ball.unitInertia() - Mat3::Identity() * 0.1).norm(), 1e-15);
  EXPECT_THROW(CapsuleCollider(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(CapsuleCollider(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(CapsuleCollider(NAN, 1.0), std::invalid_argument);
}

TEST(CapsuleCollider, InertiaMatchesSampledVolume) {
  // Deterministic grid integration of the capsule's indicator function.
  CapsuleCollider capsule(0.4, 0.7);
  const int n = 120;
  const Aabb box = capsule.localBounds();
  const Vec3 step = (box.max - box.min) / n;
  Mat3 inertia = Mat3::Zero();
  double mass = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3 p = box.min + step.cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5));
        const Vec3 axisPoint(0, std::clamp(p.y(), -0.7, 0.7), 0);
        if ((p - axisPoint).norm() > 0.4) continue;
        mass += 1.0;
        inertia += Mat3::Identity() * p.squaredNorm() - p * p.transpose();
      }
    }
  }
  inertia /= mass;
  EXPECT_NEAR(mass * step.prod(), capsule.volume(), 2e-3 * capsule.volume());
  EXPECT_LE((inertia - capsule.unitInertia()).norm(), 2e-3 * capsule.unitInertia().norm());
}

TEST(CapsuleContact, CrossedCapsulesAreExact) {
  CapsuleCollider capsule(0.2, 1.0);
  const Quat alongX(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()));
  for (const Transform& motion : testing::testMotions(3)) {
    // Cores 0.3 apart: GJK only.
    ContactResult r = collide(capsule, motion, capsule, testing::compose(motion, {Vec3(0, 0.2, 0.3), alongX}));
    testing::expectFinite(r);
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, 0.1, 1e-9);
    EXPECT_LE((r.normal - motion.rotation * Vec3::UnitZ()).norm(), 1e-9);
    EXPECT_LE((r.pointA - motion.apply(Vec3(0, 0.2, 0.2))).norm(), 1e-9);
    // Cores crossing: the Minkowski difference of the cores is flat.
    r = collide(capsule, motion, capsule, testing::compose(motion, {Vec3(0, 0.2, 0.0), alongX}));
    testing::expectFinite(r);
    EXPECT_EQ(r.status, ContactStatus::Penetrating);
    EXPECT_NEAR(r.depth, 0.4, 1e-9);
    EXPECT_NEAR(std::abs(r.normal.dot(motion.rotation * Vec3::UnitZ())), 1.0, 1e-9);
    EXPECT_LE((0.5 * (r.pointA + r.pointB) - motion.apply(Vec3(0, 0.2, 0))).norm(), 1e-9);  // the crossing
    EXPECT_NEAR((r.pointA - r.pointB).norm(), 0.4, 1e-9);
  }
}

TEST(CapsuleContact, CapsuleAgainstSphereAndBox) {
  CapsuleCollider capsule(0.25, 0.5);
  SphereCollider sphere(0.5);
  BoxCollider box(Vec3(2, 0.1, 2));
  // Sphere beside the segment's upper end, 0.7 from the axis.
  ContactResult r = collide(capsule, Transform{}, sphere, at(0.7, 0.4, 0));
  EXPECT_NEAR(r.depth, 0.05, 1e-12);
  EXPECT_LE((r.normal - Vec3::UnitX()).norm(), 1e-12);
  // Sphere past the end cap, on the axis.
  r = collide(capsule, Transform{}, sphere, at(0, 1.2, 0));
  EXPECT_NEAR(r.depth, 0.05, 1e-12);
  // Capsule standing on a slab: the lower cap dips 0.05 below the top face.
  for (const Transform& motion : testing::testMotions(9)) {
    r = collide(box, motion, capsule, testing::compose(motion, at(0.3, 0.1 + 0.75 - 0.05, -0.2)));
    testing::expectFinite(r);
    EXPECT_NEAR(r.depth, 0.05, 1e-9);
    EXPECT_LE((r.normal - motion.rotation * Vec3::UnitY()).norm(), 1e-9);
    EXPECT_LE((r.pointB - motion.apply(Vec3(0.3, 0.05, -0.2))).norm(), 1e-9);
  }
  // Lying on the slab, touching exactly: no deep contact.
  const Transform lying{Vec3(0, 0.35, 0), Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()))};
  r = collide(box, Transform{}, capsule, lying);
  testing::expectFinite(r);
  EXPECT_EQ(r.status, ContactStatus::Touching);
}

}  // namespace
}  // namespace physdbg
