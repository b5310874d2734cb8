// Cross-thread determinism (as Box2D's test pins it): the same scene stepped
// on 1, 2 and 4 threads gives the same doubles, bit for bit, after every
// step: body states, sleep and islands, contacts, manifolds and counters.
// Worlds advance in lockstep, so a failure names the first step and body
// that part. `physdbg simulate --hash` is checked end to end in
// tests/cli/thread_determinism_cli_test.cpp.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "engine/world.h"
#include "scenes/scene.h"
#include "scenes/stacking_scenes.h"

namespace physdbg {
namespace {

constexpr int threadCounts[] = {1, 2, 4};

template <typename Value>
bool sameBits(const Value& first, const Value& second) {
  return std::memcmp(&first, &second, sizeof(Value)) == 0;
}

bool sameBits(const Vec3& first, const Vec3& second) {
  return std::memcmp(first.data(), second.data(), sizeof(double) * 3) == 0;
}

bool sameBits(const Quat& first, const Quat& second) {
  return std::memcmp(first.coeffs().data(), second.coeffs().data(), sizeof(double) * 4) == 0;
}

// The first difference between two worlds, or "" when they agree.
std::string firstBodyDifference(const World& expected, const World& actual) {
  for (BodyId id = 0; id < expected.bodyCount(); ++id) {
    const RigidBody &first = expected.body(id), &second = actual.body(id);
    const std::string body = "body " + std::to_string(id) + ": ";
    if (!sameBits(first.position(), second.position())) return body + "position";
    if (!sameBits(first.orientation(), second.orientation())) return body + "orientation";
    if (!sameBits(first.linearVelocity(), second.linearVelocity())) return body + "linear velocity";
    if (!sameBits(first.angularVelocity(), second.angularVelocity())) return body + "angular velocity";
    if (expected.isAsleep(id) != actual.isAsleep(id)) return body + "asleep";
    if (expected.islandOf(id) != actual.islandOf(id)) return body + "island";
    if (expected.isPresent(id) != actual.isPresent(id)) return body + "present";
  }
  return "";
}

std::string firstContactDifference(const World& expected, const World& actual) {
  const auto &first = expected.contacts(), &second = actual.contacts();
  if (first.size() != second.size()) return "contact count";
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (first[i].a != second[i].a || first[i].b != second[i].b) return "contact " + std::to_string(i) + " pair";
    if (!sameBits(first[i].result.normal, second[i].result.normal) ||
        !sameBits(first[i].result.depth, second[i].result.depth) ||
        !sameBits(first[i].result.distance, second[i].result.distance))
      return "contact " + std::to_string(i) + " result";
  }
  const auto &firstManifolds = expected.manifolds(), &secondManifolds = actual.manifolds();
  if (firstManifolds.size() != secondManifolds.size()) return "manifold count";
  for (std::size_t i = 0; i < firstManifolds.size(); ++i) {
    const ContactManifold &first = firstManifolds[i], &second = secondManifolds[i];
    if (first.a != second.a || first.b != second.b || first.pointCount != second.pointCount)
      return "manifold " + std::to_string(i);
    for (int p = 0; p < first.pointCount; ++p)
      if (!sameBits(first.points[p].normalImpulse, second.points[p].normalImpulse))
        return "manifold " + std::to_string(i) + " point " + std::to_string(p) + " impulse";
  }
  return "";
}

std::string firstStatsDifference(const StepStats& first, const StepStats& second) {
  if (first.awakeBodies != second.awakeBodies || first.sleepingBodies != second.sleepingBodies) return "body counts";
  if (first.candidatePairs != second.candidatePairs || first.boundsRejected != second.boundsRejected)
    return "pair counts";
  if (first.contacts != second.contacts || first.manifolds != second.manifolds ||
      first.manifoldPoints != second.manifoldPoints || first.responses != second.responses)
    return "contact counts";
  if (first.narrowPhase.pairs != second.narrowPhase.pairs || first.narrowPhase.gjk != second.narrowPhase.gjk ||
      first.narrowPhase.epa != second.narrowPhase.epa || first.narrowPhase.fastPath != second.narrowPhase.fastPath)
    return "narrow-phase counters";
  if (!sameBits(first.largestPenetration, second.largestPenetration) || first.substeps != second.substeps)
    return "solver report";
  return "";
}

struct RunSummary {
  int sleptSteps = 0;   // steps after which some body was asleep
  int absentSteps = 0;  // steps after which some body was out of the run
};

// Steps the scene on every thread count in lockstep, comparing each world
// with the single-threaded one after every step.
RunSummary expectSameOnEveryThreadCount(SceneDescription scene, int steps) {
  std::vector<World> worlds;
  for (const int threads : threadCounts) {
    scene.world.threads = threads;
    worlds.push_back(buildWorld(scene));
  }
  RunSummary summary;
  for (int step = 1; step <= steps; ++step) {
    for (World& world : worlds) world.step();
    const World& reference = worlds.front();
    for (std::size_t w = 1; w < worlds.size(); ++w) {
      const std::string where = scene.name + ", " + std::to_string(threadCounts[w]) + " threads, step " +
                                std::to_string(step) + ": ";
      std::string difference = firstBodyDifference(reference, worlds[w]);
      if (difference.empty()) difference = firstContactDifference(reference, worlds[w]);
      if (difference.empty()) difference = firstStatsDifference(reference.lastStepStats(), worlds[w].lastStepStats());
      if (!difference.empty()) {
        ADD_FAILURE() << where << difference << " differs from 1 thread";
        return summary;
      }
    }
    bool asleep = false, absent = false;
    for (BodyId id = 0; id < reference.bodyCount(); ++id) {
      asleep = asleep || reference.isAsleep(id);
      absent = absent || !reference.isPresent(id);
    }
    summary.sleptSteps += asleep;
    summary.absentSteps += absent;
  }
  return summary;
}

TEST(ThreadDeterminism, BuiltInPyramid) { expectSameOnEveryThreadCount(resolveScene("pyramid"), 120); }

TEST(ThreadDeterminism, DefaultScene) { expectSameOnEveryThreadCount(resolveScene("default"), 150); }

// Tree broad phase on a wide pyramid: hundreds of bodies, so every parallel
// loop really splits.
TEST(ThreadDeterminism, WidePyramid) { expectSameOnEveryThreadCount(pyramidScene(30), 40); }

// 512 boxes, spheres, capsules and hulls: GJK, EPA and clipped manifolds of
// every kind of pair.
TEST(ThreadDeterminism, MixedPile) {
  expectSameOnEveryThreadCount(loadSceneFile(PHYSDBG_SOURCE_DIR "/scenes/mixed_pile.json"), 90);
}

TEST(ThreadDeterminism, SleepingStack) {
  const RunSummary summary = expectSameOnEveryThreadCount(resolveScene("stack"), 300);
  EXPECT_GT(summary.sleptSteps, 0) << "the stack never fell asleep: the test no longer covers sleep";
}

TEST(ThreadDeterminism, BodiesArrivingAndLeaving) {
  const RunSummary summary =
      expectSameOnEveryThreadCount(loadSceneFile(PHYSDBG_SOURCE_DIR "/scenes/arrivals.json"), 240);
  EXPECT_GT(summary.absentSteps, 0);
}

// The brute-force broad phase and the seed solver take other paths through
// the step (both orders tested, static pairs tested, no manifolds).
TEST(ThreadDeterminism, BruteForceSeedScene) {
  expectSameOnEveryThreadCount(resolveScene("balls48_bruteforce_no_static_skip"), 120);
}

}  // namespace
}  // namespace physdbg
