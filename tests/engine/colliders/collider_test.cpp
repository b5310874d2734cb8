#include <gtest/gtest.h>

#include <numbers>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"

namespace physdbg {
namespace {

TEST(BoxCollider, SupportIsTheCornerFacingTheDirection) {
  BoxCollider box(Vec3(1, 2, 3));
  EXPECT_EQ(box.localSupport(Vec3(1, -1, 1)), Vec3(1, -2, 3));
  EXPECT_EQ(box.localSupport(Vec3(-0.1, 5, -2)), Vec3(-1, 2, -3));
}

TEST(BoxCollider, MassPropertiesMatchTheTextbook) {
  BoxCollider box(Vec3(0.5, 1.0, 1.5));  // 1 x 2 x 3
  EXPECT_DOUBLE_EQ(box.volume(), 6.0);
  const Mat3 inertia = box.unitInertia();
  EXPECT_DOUBLE_EQ(inertia(0, 0), (4.0 + 9.0) / 12.0);
  EXPECT_DOUBLE_EQ(inertia(1, 1), (1.0 + 9.0) / 12.0);
  EXPECT_DOUBLE_EQ(inertia(2, 2), (1.0 + 4.0) / 12.0);
  EXPECT_EQ(inertia(0, 1), 0.0);
}

TEST(BoxCollider, WorldBoundsOfARotatedBoxAreTight) {
  BoxCollider box(Vec3(1, 1, 1));
  Transform transform{Vec3(10, 0, 0), Quat(Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()))};
  const Aabb bounds = box.worldBounds(transform);
  EXPECT_NEAR(bounds.max.x(), 10 + std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(bounds.max.y(), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(bounds.max.z(), 1.0, 1e-12);
}

TEST(SphereCollider, SupportAndMass) {
  SphereCollider sphere(2.0);
  EXPECT_TRUE(sphere.localSupport(Vec3(0, 3, 4)).isApprox(Vec3(0, 1.2, 1.6)));
  EXPECT_EQ(sphere.localSupport(Vec3::Zero()).norm(), 2.0);
  EXPECT_NEAR(sphere.volume(), 4.0 / 3.0 * std::numbers::pi * 8.0, 1e-12);
  EXPECT_DOUBLE_EQ(sphere.unitInertia()(2, 2), 0.4 * 4.0);
  Transform transform{Vec3(1, 2, 3), Quat::Identity()};
  EXPECT_EQ(sphere.support(transform, Vec3(0, 0, -1)), Vec3(1, 2, 1));
}

}  // namespace
}  // namespace physdbg
