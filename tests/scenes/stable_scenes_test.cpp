// The stability scene builders: bad parameters are rejected, and the scenes
// start in the state their headers promise (resting contact, no overlap).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "engine/narrowphase/narrow_phase.h"
#include "scenes/stability_scenes.h"

namespace physdbg {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

TEST(StableScenes, BuildersRejectBadParameters) {
  EXPECT_THROW(massStackScene({}), std::invalid_argument);
  EXPECT_THROW(massStackScene({1.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(massStackScene({nan}), std::invalid_argument);
  EXPECT_THROW(slidingBlockScene(-1.0, 0.3, 0.5), std::invalid_argument);
  EXPECT_THROW(slidingBlockScene(1.0, nan, 0.5), std::invalid_argument);
  EXPECT_THROW(slidingBlockScene(1.0, 0.3, -0.5), std::invalid_argument);
  EXPECT_THROW(slopeScene(0.0, 0.6), std::invalid_argument);
  EXPECT_THROW(slopeScene(0.5 * std::numbers::pi, 0.6), std::invalid_argument);
  EXPECT_THROW(slopeScene(0.3, -0.1), std::invalid_argument);
  EXPECT_THROW(bulletScene(std::numeric_limits<double>::infinity(), BulletShape::Sphere), std::invalid_argument);
  EXPECT_THROW(overlappingBoxesScene(1.0), std::invalid_argument);
  EXPECT_THROW(overlappingBoxesScene(-0.1), std::invalid_argument);
  EXPECT_THROW(elasticDropScene(-1.0), std::invalid_argument);
}

// Distance between the surfaces of bodies a and b as the scene builds them.
double gap(const SceneDescription& scene, int a, int b) {
  const BodyDefinition &first = scene.bodies[a], &second = scene.bodies[b];
  const ContactResult result = collide(*first.collider, {first.position, first.orientation}, *second.collider,
                                       {second.position, second.orientation}, NarrowPhaseOptions{});
  return result.status == ContactStatus::Separated ? result.distance : -result.depth;
}

TEST(StableScenes, RestingScenesStartInExactContact) {
  EXPECT_NEAR(gap(slopeScene(0.7, 0.6), 0, 1), 0.0, 1e-9);
  EXPECT_NEAR(gap(slidingBlockScene(4.0, 0.3, 0.5), 0, 1), 0.0, 1e-9);
  const SceneDescription stack = massStackScene({1.0, 100.0});
  EXPECT_NEAR(gap(stack, 0, 1), 0.0, 1e-9);
  EXPECT_NEAR(gap(stack, 1, 2), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(stack.bodies[2].mass, 100.0);
  EXPECT_NEAR(gap(overlappingBoxesScene(0.25), 1, 2), -0.25, 1e-9);
  EXPECT_NEAR(gap(elasticDropScene(2.0), 0, 1), 2.0, 1e-9);
  EXPECT_NEAR(gap(bulletScene(200.0, BulletShape::Box), 0, 1), 5.0 - bulletSize - wallHalfThickness, 1e-9);
}

TEST(StableScenes, SlopeDownhillIsAlongTheTiltedFaceAndDescends) {
  const double angle = 0.4;
  const SceneDescription scene = slopeScene(angle, 0.6);
  const Vec3 normal = scene.bodies[0].orientation * Vec3::UnitY();
  EXPECT_NEAR(slopeDownhill(angle).dot(normal), 0.0, 1e-12);
  EXPECT_NEAR(slopeDownhill(angle).y(), -std::sin(angle), 1e-12);
  EXPECT_NEAR(slopeDownhill(angle).norm(), 1.0, 1e-12);
}

}  // namespace
}  // namespace physdbg
