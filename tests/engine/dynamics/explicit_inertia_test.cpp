// BodyDefinition::localInertia: a given tensor replaces the collider's, and
// inertiaTensorProblem refuses what no body has (asymmetric, not positive
// definite, principal moments past the triangle inequality).
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>

#include "engine/colliders/sphere_collider.h"
#include "engine/dynamics/rigid_body.h"

namespace physdbg {
namespace {

Mat3 tensor(double xx, double yy, double zz, double xy = 0, double xz = 0, double yz = 0) {
  Mat3 m;
  m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return m;
}

BodyDefinition sphereWith(const Mat3& inertia) {
  BodyDefinition body;
  body.collider = std::make_shared<SphereCollider>(0.5);
  body.mass = 3;
  body.localInertia = inertia;
  return body;
}

TEST(ExplicitInertia, ReplacesTheCollidersAndTurnsTheBody) {
  const Mat3 given = tensor(1, 2, 2.5, 0.1, 0, -0.2);
  RigidBody body(sphereWith(given));
  EXPECT_EQ(body.localInertia(), given);
  EXPECT_EQ(body.mass(), 3.0);
  const Vec3 torque(0.3, -0.2, 0.5);
  body.addTorque(torque, ForceMode::Impulse);
  body.beginStep(Vec3::Zero());
  EXPECT_NEAR((body.angularVelocity() - given.inverse() * torque).norm(), 0.0, 1e-14);
}

TEST(ExplicitInertia, ProblemsAreNamed) {
  EXPECT_EQ(inertiaTensorProblem(tensor(1, 1, 1)), "");
  EXPECT_EQ(inertiaTensorProblem(tensor(1, 1, 2)), "");                 // a flat plate: equality
  EXPECT_EQ(inertiaTensorProblem(tensor(1e-200, 1e-200, 1e-200)), "");  // scale does not matter
  Mat3 nearlySymmetric = tensor(1, 1, 1);
  nearlySymmetric(0, 1) = 1e-10;
  EXPECT_EQ(inertiaTensorProblem(nearlySymmetric), "");
  Mat3 asymmetric = tensor(1, 1, 1);
  asymmetric(0, 1) = 1e-8;
  EXPECT_NE(inertiaTensorProblem(asymmetric).find("not symmetric"), std::string::npos);
  EXPECT_NE(inertiaTensorProblem(tensor(1, 1, 2.01)).find("triangle inequality"), std::string::npos);
  EXPECT_NE(inertiaTensorProblem(tensor(1, 1, 1, 2)).find("not positive definite"), std::string::npos);
  EXPECT_NE(inertiaTensorProblem(tensor(1, 1, -1)).find("not positive definite"), std::string::npos);
  EXPECT_NE(inertiaTensorProblem(Mat3::Zero()).find("zero"), std::string::npos);
  EXPECT_NE(inertiaTensorProblem(tensor(1, std::numeric_limits<double>::infinity(), 1)).find("not finite"),
            std::string::npos);
}

TEST(ExplicitInertia, BadTensorsAndNonDynamicBodiesAreRefused) {
  EXPECT_THROW(RigidBody(sphereWith(tensor(1, 1, 3))), std::invalid_argument);
  EXPECT_THROW(RigidBody(sphereWith(tensor(1, 1, 1, 5))), std::invalid_argument);
  BodyDefinition fixed = sphereWith(tensor(1, 1, 1));
  fixed.isStatic = true;
  EXPECT_THROW(RigidBody{fixed}, std::invalid_argument);
  fixed.isStatic = false;
  fixed.isKinematic = true;
  EXPECT_THROW(RigidBody{fixed}, std::invalid_argument);
}

}  // namespace
}  // namespace physdbg
