// WorldSettings::bruteForceBothOrders, the design's brute force: the narrow
// phase runs for A-B and for B-A, and the response still comes once per pair.
// So the narrow-phase count doubles and nothing else changes.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/world.h"

namespace physdbg {
namespace {

// Spheres and boxes (so both the sphere fast path and GJK/EPA run) dropped
// in a loose heap onto a floor, thrown sideways so they keep meeting. The
// both-orders baseline tests every pair anew, so the single-order run does
// too: taking answers again (contact_reuse.h) is compared elsewhere.
World heap(SolverKind solver, BroadPhaseKind broadPhase, bool bothOrders) {
  WorldSettings settings;
  settings.broadPhase = broadPhase;
  settings.bruteForceBothOrders = bothOrders;
  settings.reuseContacts = false;
  settings.allowSleep = false;
  settings.solver.kind = solver;
  World world(settings);
  BodyDefinition floor;
  floor.collider = std::make_shared<BoxCollider>(Vec3(5, 0.5, 5));
  floor.position = Vec3(0, -0.5, 0);
  floor.isStatic = true;
  world.addBody(floor);
  for (int i = 0; i < 12; ++i) {
    BodyDefinition body;
    if (i % 2 == 0)
      body.collider = std::make_shared<SphereCollider>(0.4);
    else
      body.collider = std::make_shared<BoxCollider>(Vec3(0.35, 0.35, 0.35));
    body.position = Vec3(-1.2 + 0.8 * (i % 4), 0.6 + 0.9 * (i / 4), -0.4 + 0.3 * (i % 3));
    body.linearVelocity = Vec3(std::sin(1.7 * i), 0.0, std::cos(1.3 * i));
    world.addBody(body);
  }
  return world;
}

void expectDoubledNarrowPhaseAndSameMotion(SolverKind solver, BroadPhaseKind broadPhase) {
  World once = heap(solver, broadPhase, false);
  World twice = heap(solver, broadPhase, true);
  long long tested = 0;
  for (int step = 1; step <= 120; ++step) {
    once.step();
    twice.step();
    const StepStats &a = once.lastStepStats(), &b = twice.lastStepStats();
    ASSERT_EQ(b.candidatePairs, a.candidatePairs) << "step " << step;
    ASSERT_EQ(b.narrowPhase.pairs, 2 * a.narrowPhase.pairs) << "step " << step;
    ASSERT_EQ(b.contacts, a.contacts) << "step " << step;
    ASSERT_EQ(b.responses, a.responses) << "step " << step;
    tested += a.narrowPhase.pairs;
    for (BodyId id = 0; id < once.bodyCount(); ++id) {
      ASSERT_EQ(twice.body(id).position(), once.body(id).position()) << "step " << step << " body " << id;
      ASSERT_EQ(twice.body(id).orientation().coeffs(), once.body(id).orientation().coeffs())
          << "step " << step << " body " << id;
      ASSERT_EQ(twice.body(id).linearVelocity(), once.body(id).linearVelocity()) << "step " << step << " body " << id;
      ASSERT_EQ(twice.body(id).angularVelocity(), once.body(id).angularVelocity())
          << "step " << step << " body " << id;
    }
  }
  EXPECT_GT(tested, 0);  // the heap did reach the narrow phase
}

TEST(BruteForceBothOrders, SeedSolverDoublesNarrowPhaseAndKeepsStatesBitIdentical) {
  expectDoubledNarrowPhaseAndSameMotion(SolverKind::Seed, BroadPhaseKind::BruteForce);
}

TEST(BruteForceBothOrders, SequentialImpulsesDoubleNarrowPhaseAndKeepStatesBitIdentical) {
  expectDoubledNarrowPhaseAndSameMotion(SolverKind::SequentialImpulse, BroadPhaseKind::BruteForce);
}

}  // namespace
}  // namespace physdbg
