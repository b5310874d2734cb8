// A pair whose bodies stayed within the reuse tolerance takes its last
// answer again, carried to the current poses; the carried answer must agree
// with a new test there to within what the tolerance allows.
#include "engine/contacts/contact_reuse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/colliders/box_collider.h"
#include "engine/contacts/manifold_builder.h"
#include "engine/narrowphase/narrow_phase.h"
#include "engine/world.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

constexpr double reach = 0.02;

ReusableContact computeAt(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb) {
  ReusableContact kept;
  kept.pair = {0, 1};
  kept.a = ta;
  kept.b = tb;
  kept.result = collide(a, ta, b, tb);
  ManifoldScratch scratch;
  buildManifold(a, ta, b, tb, kept.result, reach, scratch, kept.manifold);
  return kept;
}

Transform nudged(const Transform& pose, std::mt19937& random, const ContactReuseTolerance& tolerance) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const Vec3 shift(unit(random), unit(random), unit(random));
  const Vec3 axis = Vec3(unit(random), unit(random), unit(random)).normalized();
  Transform moved = pose;
  moved.position += 0.5 * tolerance.distance * shift.normalized();
  moved.rotation = (Quat(Eigen::AngleAxisd(0.9 * tolerance.angle, axis)) * pose.rotation).normalized();
  return moved;
}

// A unit box resting on a slab, tilted and shifted at random within a few
// millimetres of touching; both bodies then nudged within the tolerance. The
// carried manifold has the new test's points (same feature ids), separations
// within the distance the tolerance lets a point move (0.1 mm + 2e-4 rad x
// 1 m from the centre, both bodies), and a normal within twice its angle.
TEST(ContactReuse, ACarriedAnswerAgreesWithANewTestWithinTheTolerance) {
  const BoxCollider slab(Vec3(5, 0.5, 5)), box(Vec3::Constant(0.5));
  const ContactReuseTolerance tolerance;
  const double pointMove = 2.0 * (tolerance.distance + tolerance.angle * 1.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int carried = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Transform slabPose{Vec3(0, -0.5, 0), Quat::Identity()};
    const Vec3 tiltAxis = Vec3(unit(random), 0, unit(random)).normalized();
    const Transform boxPose{Vec3(unit(random), 0.5 + 0.004 * unit(random), unit(random)),
                            Quat(Eigen::AngleAxisd(0.002 * unit(random), tiltAxis))};
    const ReusableContact kept = computeAt(slab, slabPose, box, boxPose);
    const Transform slabNow = nudged(slabPose, random, tolerance), boxNow = nudged(boxPose, random, tolerance);
    ASSERT_TRUE(stillHolds(kept, slabNow, boxNow, tolerance));
    ContactResult result;
    if (!carryResult(kept, slabNow, boxNow, result)) continue;  // the sign changed: tested anew
    ++carried;
    const ReusableContact fresh = computeAt(slab, slabNow, box, boxNow);
    EXPECT_EQ(result.status, fresh.result.status);
    EXPECT_NEAR(result.distance, fresh.result.distance, pointMove);
    EXPECT_NEAR(result.depth, fresh.result.depth, pointMove);
    ContactManifold manifold;
    carryManifold(kept, slabNow, boxNow, manifold);
    EXPECT_LT(std::acos(std::min(1.0, manifold.normal.dot(fresh.manifold.normal))), 2.0 * tolerance.angle + 1e-9);
    ASSERT_EQ(manifold.pointCount, fresh.manifold.pointCount) << "trial " << trial;
    for (int p = 0; p < manifold.pointCount; ++p) {
      EXPECT_EQ(manifold.points[p].featureId, fresh.manifold.points[p].featureId);
      EXPECT_NEAR(manifold.points[p].separation, fresh.manifold.points[p].separation, pointMove);
      EXPECT_LT((manifold.points[p].pointB - fresh.manifold.points[p].pointB).norm(), pointMove);
    }
  }
  EXPECT_GT(carried, 150);
}

// Both bodies moved by the same rigid motion (a metre and 30 degrees): the
// new test's answer is the old one moved with them, so carrying must give it
// to rounding. (carryResult and carryManifold do not check the tolerance.)
TEST(ContactReuse, CarryingFollowsARigidMotionOfBothBodiesExactly) {
  const BoxCollider slab(Vec3(5, 0.5, 5)), box(Vec3::Constant(0.5));
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Transform slabPose{Vec3(0, -0.5, 0), Quat::Identity()};
    const Transform boxPose{Vec3(unit(random), 0.5 + 0.004 * unit(random), unit(random)),
                            Quat(Eigen::AngleAxisd(0.002 * unit(random), Vec3::UnitX()))};
    const ReusableContact kept = computeAt(slab, slabPose, box, boxPose);
    const Transform motion{Vec3(unit(random), unit(random), unit(random)),
                           Quat(Eigen::AngleAxisd(0.5, Vec3(unit(random), unit(random), unit(random)).normalized()))};
    const auto moved = [&](const Transform& pose) {
      return Transform{motion.apply(pose.position), (motion.rotation * pose.rotation).normalized()};
    };
    const ReusableContact fresh = computeAt(slab, moved(slabPose), box, moved(boxPose));
    ContactResult result;
    ASSERT_TRUE(carryResult(kept, moved(slabPose), moved(boxPose), result));
    EXPECT_EQ(result.status, fresh.result.status);
    EXPECT_NEAR(result.depth, fresh.result.depth, 1e-9);
    EXPECT_NEAR(result.distance, fresh.result.distance, 1e-9);
    EXPECT_LT((result.normal - fresh.result.normal).norm(), 1e-9);
    ContactManifold manifold;
    carryManifold(kept, moved(slabPose), moved(boxPose), manifold);
    EXPECT_LT((manifold.normal - fresh.manifold.normal).norm(), 1e-9);
    ASSERT_EQ(manifold.pointCount, fresh.manifold.pointCount);
    for (int p = 0; p < manifold.pointCount; ++p) {
      EXPECT_EQ(manifold.points[p].featureId, fresh.manifold.points[p].featureId);
      EXPECT_NEAR(manifold.points[p].separation, fresh.manifold.points[p].separation, 1e-9);
      EXPECT_LT((manifold.points[p].pointA - fresh.manifold.points[p].pointA).norm(), 1e-9);
      EXPECT_LT((manifold.points[p].pointB - fresh.manifold.points[p].pointB).norm(), 1e-9);
    }
  }
}

TEST(ContactReuse, ABodyMovedBeyondTheToleranceIsTestedAnew) {
  const BoxCollider slab(Vec3(5, 0.5, 5)), box(Vec3::Constant(0.5));
  const Transform slabPose{Vec3(0, -0.5, 0), Quat::Identity()}, boxPose{Vec3(0, 0.499, 0), Quat::Identity()};
  const ReusableContact kept = computeAt(slab, slabPose, box, boxPose);
  const ContactReuseTolerance tolerance;
  EXPECT_TRUE(stillHolds(kept, slabPose, boxPose, tolerance));
  Transform shifted = boxPose;
  shifted.position.x() += 1.5 * tolerance.distance;
  EXPECT_FALSE(stillHolds(kept, slabPose, shifted, tolerance));
  Transform turned = boxPose;
  turned.rotation = Quat(Eigen::AngleAxisd(1.5 * tolerance.angle, Vec3::UnitY()));
  EXPECT_FALSE(stillHolds(kept, slabPose, turned, tolerance));
  Transform liftedSlab = slabPose;
  liftedSlab.position.y() += 1.5 * tolerance.distance;
  EXPECT_FALSE(stillHolds(kept, liftedSlab, boxPose, tolerance));
}

// A penetrating answer carried to where the bodies are apart is not taken.
// (carryResult does not check the tolerance: that is stillHolds' job.)
TEST(ContactReuse, AnAnswerWhoseSignChangedIsNotCarried) {
  const BoxCollider slab(Vec3(5, 0.5, 5)), box(Vec3::Constant(0.5));
  const Transform slabPose{Vec3(0, -0.5, 0), Quat::Identity()};
  const ReusableContact kept = computeAt(slab, slabPose, box, Transform{Vec3(0, 0.499, 0), Quat::Identity()});
  ASSERT_EQ(kept.result.status, ContactStatus::Penetrating);
  ContactResult result;
  EXPECT_TRUE(carryResult(kept, slabPose, Transform{Vec3(0, 0.4995, 0), Quat::Identity()}, result));
  EXPECT_NEAR(result.depth, 5e-4, 1e-12);
  EXPECT_FALSE(carryResult(kept, slabPose, Transform{Vec3(0, 0.5005, 0), Quat::Identity()}, result));
}

// The store keeps each answer in its slot across builds: carried answers
// keep their contents, dropped ones are gone, and a fresh answer may take a
// dropped one's slot without disturbing the others.
TEST(KeptAnswers, CarriedAnswersKeepTheirContentsAndDroppedOnesGo) {
  KeptAnswers kept;
  const auto mark = [](const ReusableContact* entry) { return entry ? entry->result.depth : -1.0; };
  kept.beginNext();
  for (std::uint32_t b : {2u, 3u, 4u}) kept.fresh({1, b}).result.depth = b;
  kept.endNext();
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(mark(kept.find({1, 3})), 3.0);
  EXPECT_EQ(kept.find({1, 5}), nullptr);

  kept.beginNext();
  kept.carry({1, 2});
  kept.carry({1, 4});
  kept.fresh({1, 7}).result.depth = 7;
  kept.carry({1, 9});  // never kept: nothing to carry
  kept.endNext();
  EXPECT_EQ(kept.size(), 3u);
  EXPECT_EQ(mark(kept.find({1, 2})), 2.0);
  EXPECT_EQ(kept.find({1, 3}), nullptr);
  EXPECT_EQ(mark(kept.find({1, 4})), 4.0);
  EXPECT_EQ(mark(kept.find({1, 7})), 7.0);

  kept.beginNext();  // (1,3)'s slot is free again
  kept.fresh({0, 1}).result.depth = 10;
  kept.carry({1, 2});
  kept.carry({1, 7});
  kept.endNext();
  EXPECT_EQ(mark(kept.find({0, 1})), 10.0);
  EXPECT_EQ(mark(kept.find({1, 2})), 2.0);
  EXPECT_EQ(mark(kept.find({1, 7})), 7.0);
  EXPECT_EQ(kept.find({1, 4}), nullptr);
}

// Four boxes at rest on a floor: once settled their pairs are taken again,
// and the column ends where it ends with every pair tested anew, to within
// a tenth of a millimetre.
TEST(ContactReuse, ARestingColumnTakesItsAnswersAgainAndStandsTheSame) {
  const auto column = [](bool reuse) {
    WorldSettings settings;
    settings.allowSleep = false;
    settings.reuseContacts = reuse;
    World world(settings);
    world.addBody(testbodies::floorSlab());
    for (int i = 0; i < 4; ++i) world.addBody(testbodies::box(Vec3(0, 0.5 + i, 0)));
    return world;
  };
  World reused = column(true), fresh = column(false);
  long long taken = 0;
  for (int step = 0; step < 240; ++step) {
    reused.step();
    fresh.step();
    taken += reused.lastStepStats().narrowPhase.reused;
    EXPECT_EQ(fresh.lastStepStats().narrowPhase.reused, 0);
  }
  EXPECT_GT(taken, 4 * 120);  // most of the 4 pairs x 240 steps
  for (BodyId id = 1; id <= 4; ++id)
    EXPECT_LT((reused.body(id).position() - fresh.body(id).position()).norm(), 1e-4) << "box " << id;
}

}  // namespace
}  // namespace physdbg
