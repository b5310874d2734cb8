// restingLoads: the weight each contact holds up, against hand-summed
// answers for stacks, a bridge and contacts that hold nothing up; and
// seedNewContacts, which starts only new, touching contacts at that load.
#include "engine/solver/resting_load.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "engine/colliders/box_collider.h"
#include "engine/world.h"
#include "scenes/body_builders.h"

namespace physdbg {
namespace {

const Vec3 up = Vec3::UnitY();

BodyDefinition box(const Vec3& position, const Vec3& halfExtents, double mass) {
  return dynamicBody(std::make_shared<BoxCollider>(halfExtents), position, mass);
}

// One step finds the manifolds; the loads are then read off them.
struct SteppedWorld {
  World world;
  std::vector<bool> movable;
  explicit SteppedWorld(const std::vector<BodyDefinition>& bodies) {
    for (const BodyDefinition& body : bodies) world.addBody(body);
    world.step();
    for (const RigidBody& body : world.bodies()) movable.push_back(!body.isStatic());
  }
  // Load of the manifold between bodies a < b, or -1 when they have none.
  double load(std::uint32_t a, std::uint32_t b) const {
    const std::vector<double> touching(world.manifolds().size(), 0.005);
    const std::vector<double> loads = restingLoads(world.bodies(), movable, world.manifolds(), touching, up);
    for (std::size_t m = 0; m < loads.size(); ++m)
      if (world.manifolds()[m].a == a && world.manifolds()[m].b == b) return loads[m];
    return -1.0;
  }
};

TEST(RestingLoad, EachContactOfAStackHoldsEverythingAboveIt) {
  const Vec3 half(0.5, 0.5, 0.5);
  const SteppedWorld stack({staticBox(Vec3(0, -0.5, 0), Vec3(5, 0.5, 5)), box(Vec3(0, 0.5, 0), half, 1.0),
                            box(Vec3(0, 1.5, 0), half, 2.0), box(Vec3(0, 2.5, 0), half, 3.0)});
  EXPECT_NEAR(stack.load(0, 1), 6.0, 1e-12);
  EXPECT_NEAR(stack.load(1, 2), 5.0, 1e-12);
  EXPECT_NEAR(stack.load(2, 3), 3.0, 1e-12);
}

TEST(RestingLoad, ABridgeSplitsItsWeightBetweenItsTwoPiers) {
  const SteppedWorld bridge(
      {staticBox(Vec3(0, -0.5, 0), Vec3(5, 0.5, 5)), box(Vec3(-1.5, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0),
       box(Vec3(1.5, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0), box(Vec3(0, 1.25, 0), Vec3(2.0, 0.25, 0.5), 4.0)});
  EXPECT_NEAR(bridge.load(1, 3), 2.0, 1e-12);
  EXPECT_NEAR(bridge.load(2, 3), 2.0, 1e-12);
  EXPECT_NEAR(bridge.load(0, 1), 3.0, 1e-12);
  EXPECT_NEAR(bridge.load(0, 2), 3.0, 1e-12);
}

TEST(RestingLoad, AWallHoldsNothingUp) {
  // A box resting on the floor and touching a wall beside it.
  const SteppedWorld leaning({staticBox(Vec3(0, -0.5, 0), Vec3(5, 0.5, 5)), staticBox(Vec3(1.0, 1, 0), Vec3(0.5, 1, 1)),
                              box(Vec3(0, 0.5, 0), Vec3(0.5, 0.5, 0.5), 1.0)});
  EXPECT_NEAR(leaning.load(0, 2), 1.0, 1e-12);
  EXPECT_EQ(leaning.load(1, 2), 0.0);
}

TEST(RestingLoad, ABodyFallingTowardsTheFloorHoldsNothing) {
  World world;
  world.addBody(staticBox(Vec3(0, -0.5, 0), Vec3(5, 0.5, 5)));
  world.addBody(box(Vec3(0, 3, 0), Vec3(0.5, 0.5, 0.5), 1.0));
  world.step();
  EXPECT_TRUE(restingLoads(world.bodies(), std::vector<bool>{false, true}, world.manifolds(), {}, up).empty());
}

ContactManifold manifoldWithSeparations(std::initializer_list<double> separations) {
  ContactManifold manifold;
  for (double separation : separations) manifold.points[manifold.pointCount++].separation = separation;
  return manifold;
}

TEST(RestingLoad, SeedingStartsOnlyNewTouchingPointsAtTheirShare) {
  std::vector<ContactManifold> manifolds = {manifoldWithSeparations({-0.001, 0.0, 0.02}),
                                            manifoldWithSeparations({-0.001, -0.001})};
  manifolds[1].points[0].normalImpulse = 0.5;  // carried over: left as it is
  const double gravity = 10.0, h = 0.01, touching = 0.005;
  for (ContactManifold& manifold : manifolds) seedNewContact(manifold, 3.0, touching, gravity, h);
  // 3 kg x 10 m/s^2 x 0.01 s over the two touching points; the point 2 cm
  // away is speculative and holds nothing.
  EXPECT_NEAR(manifolds[0].points[0].normalImpulse, 0.15, 1e-15);
  EXPECT_NEAR(manifolds[0].points[1].normalImpulse, 0.15, 1e-15);
  EXPECT_EQ(manifolds[0].points[2].normalImpulse, 0.0);
  EXPECT_EQ(manifolds[1].points[0].normalImpulse, 0.5);
  EXPECT_EQ(manifolds[1].points[1].normalImpulse, 0.0);
  EXPECT_EQ(touchingPoints(manifolds[0], touching), 2);
}

}  // namespace
}  // namespace physdbg
