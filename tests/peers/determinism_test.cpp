// Determinism: the same scene stepped on 1, 2 and 4 threads gives the same
// states bit for bit, step after step, and falls asleep on the same step; a
// state saved and loaded again as a scene file continues bit for bit. Scenes
// are JSON loaded with the scenes library. Cases from Box2D v3's
// test/test_determinism.c (MultithreadingTest) and test/test_restitution.c
// (WorkerParityTest), Jolt's UnitTests/Physics/PhysicsDeterminismTests.cpp
// (TestGridOfBoxesDiscrete) and Bullet's
// test/BulletDynamics/test_deterministic_save_and_restore.cpp.
#include <cstdio>
#include <string>
#include <vector>

#include "tests/peers/peer_test_support.h"

namespace physdbg::peers {
namespace {

constexpr int kThreadCounts[] = {1, 2, 4};

struct RunTrace {
  std::vector<std::uint64_t> hashes;  // after every step
  int sleepStep = -1;                 // first step after which every dynamic body sleeps
};

RunTrace runScene(const std::string& json, int threads, int maxSteps, bool stopWhenAsleep) {
  SceneDescription scene = parseScene(json, "determinism.json");
  scene.world.threads = threads;
  World world = buildWorld(scene);
  RunTrace run;
  for (int step = 1; step <= maxSteps; ++step) {
    world.step();
    run.hashes.push_back(stateHash(world));
    bool allAsleep = true;
    for (BodyId id = 0; id < world.bodyCount(); ++id)
      if (world.body(id).isDynamic() && !world.isAsleep(id)) allAsleep = false;
    if (allAsleep && run.sleepStep < 0) {
      run.sleepStep = step;
      if (stopWhenAsleep) break;
    }
  }
  return run;
}

// The first step whose hashes differ, or 0.
int firstDifference(const RunTrace& a, const RunTrace& b) {
  const std::size_t n = std::min(a.hashes.size(), b.hashes.size());
  for (std::size_t i = 0; i < n; ++i)
    if (a.hashes[i] != b.hashes[i]) return static_cast<int>(i) + 1;
  return a.hashes.size() == b.hashes.size() ? 0 : static_cast<int>(n) + 1;
}

// Box2D test_determinism.c::MultithreadingTest (a falling pile until it
// sleeps; the sleep step and the state hash must equal fixed values for
// every worker count) and Jolt PhysicsDeterminismTests.cpp::
// TestGridOfBoxesDiscrete (every body's state equal, ==). Here a grid of 80
// tilted boxes (repeat) dropped on a floor, on 1, 2 and 4 threads. Ours:
// the hash of every body's state equal after every step, the same sleep
// step, bit for bit.
TEST(PeerDeterminism, FallingGridOfBoxesGivesTheSameBitsOnOneTwoAndFourThreads) {
  const std::string json = R"({"bodies": [
      {"shape": {"box": {"half_extents": [20, 1, 20]}}, "position": [0, -1, 0], "static": true},
      {"shape": {"box": {"half_extents": [0.4, 0.3, 0.5]}}, "position": [-1.7, 1.0, -1.3],
       "orientation": [0.98, 0.1, 0.15, 0.05], "angular_velocity": [0.3, -0.2, 0.5],
       "repeat": {"count": [4, 5, 4], "spacing": [1.13, 0.9, 0.97]}}]})";
  std::vector<RunTrace> runs;
  for (const int threads : kThreadCounts) runs.push_back(runScene(json, threads, 600, true));
  measured("sleep_step", runs[0].sleepStep);
  EXPECT_GT(runs[0].sleepStep, 0) << "the pile never fell asleep";
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(firstDifference(runs[0], runs[i]), 0) << kThreadCounts[i] << " threads";
    EXPECT_EQ(runs[i].sleepStep, runs[0].sleepStep) << kThreadCounts[i] << " threads";
  }
  char hash[32];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(runs[0].hashes.back()));
  ::testing::Test::RecordProperty("final_hash", hash);
}

// Box2D test_restitution.c::WorkerParityTest: 20 balls of restitution 0.6
// dropped side by side on a ground of 0.6 (gravity 10, no sleep), 200
// steps; the state hash must be equal on 0, 1 and 4 workers (the bounce's
// per-point state crosses the split). Ours: equal after every step on 1, 2
// and 4 threads.
TEST(PeerDeterminism, BouncingBallsGiveTheSameBitsOnEveryThreadCount) {
  std::string bodies = R"({"shape": {"box": {"half_extents": [40, 1, 5]}}, "position": [0, -1, 0],
                           "static": true, "restitution": 0.6})";
  for (int i = 0; i < 20; ++i) {
    char ball[256];
    std::snprintf(ball, sizeof ball,
                  R"(, {"shape": {"sphere": {"radius": 0.5}}, "position": [%.17g, %.17g, 0], "restitution": 0.6})",
                  -10.0 + 1.05 * i, 3.0 + 0.13 * i);
    bodies += ball;
  }
  const std::string json = R"({"gravity": [0, -10, 0], "allow_sleep": false, "bodies": [)" + bodies + "]}";
  std::vector<RunTrace> runs;
  for (const int threads : kThreadCounts) runs.push_back(runScene(json, threads, 200, false));
  for (std::size_t i = 1; i < runs.size(); ++i)
    EXPECT_EQ(firstDifference(runs[0], runs[i]), 0) << kThreadCounts[i] << " threads";
  measured("steps_compared", static_cast<double>(runs[0].hashes.size()));
}

// Bullet test_deterministic_save_and_restore.cpp::DeterministicSaveRestore:
// three small boxes (0.1 m half extent) thrown from 25 m (gravity 10, dt
// 0.01 s) are saved once they have contacts, restored into a new world with
// their manifolds, and both worlds run until nothing moves: the resting
// positions must agree (EXPECT_FLOAT_EQ, 4 float ULPs). physdbg saves no
// contacts, so the state is saved on the last step before any contact
// exists (no manifold) and written back as a scene file (positions,
// orientations and velocities to 17 digits). Ours: the restored run equals
// the original after every step, bit for bit, until all sleep.
TEST(PeerDeterminism, StateSavedAsASceneFileBeforeContactContinuesBitForBit) {
  const auto boxes = [](const char* states) {
    return std::string(R"({"gravity": [0, -10, 0], "dt": 0.01, "bodies": [
        {"shape": {"box": {"half_extents": [50, 50, 50]}}, "position": [0, -50, 0], "static": true})") +
           states + "]}";
  };
  const std::string original = boxes(R"(,
        {"shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [2, 25, 0], "velocity": [-1, 0, 1]},
        {"shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [2, 25, 2], "velocity": [-1, 0, -1]},
        {"shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [0, 25, 1], "velocity": [1, 0, 0]})");
  World world = sceneWorld(original, "bullet_boxes.json");
  // Step until the step after which a manifold first exists; keep the state before it.
  std::string saved;
  int savedStep = -1;
  for (int step = 0; step < 1000 && savedStep < 0; ++step) {
    std::string states;
    for (BodyId id = 1; id < world.bodyCount(); ++id) {
      const RigidBody& body = world.body(id);
      const Quat& q = body.orientation();
      char text[512];
      std::snprintf(text, sizeof text,
                    R"(, {"shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [%.17g, %.17g, %.17g],
                    "orientation": [%.17g, %.17g, %.17g, %.17g], "velocity": [%.17g, %.17g, %.17g],
                    "angular_velocity": [%.17g, %.17g, %.17g]})",
                    body.position().x(), body.position().y(), body.position().z(), q.w(), q.x(), q.y(), q.z(),
                    body.linearVelocity().x(), body.linearVelocity().y(), body.linearVelocity().z(),
                    body.angularVelocity().x(), body.angularVelocity().y(), body.angularVelocity().z());
      states += text;
    }
    world.step();
    if (!world.manifolds().empty()) {
      saved = states;
      savedStep = step;
    }
  }
  ASSERT_GE(savedStep, 0) << "the boxes never reached the floor";
  measured("saved_at_step", savedStep);
  // The original from the saved step on, against the restored scene.
  World first = sceneWorld(original, "bullet_boxes.json");
  stepN(first, savedStep);
  World restored = sceneWorld(boxes(saved.c_str()), "bullet_boxes_restored.json");
  int steps = 0, differing = -1;
  for (; steps < 3000; ++steps) {
    first.step();
    restored.step();
    if (stateHash(first) != stateHash(restored)) {
      differing = steps + 1;
      break;
    }
    bool allAsleep = true;
    for (BodyId id = 1; id < first.bodyCount(); ++id) allAsleep = allAsleep && first.isAsleep(id);
    if (allAsleep) break;
  }
  measured("steps_compared", steps);
  EXPECT_EQ(differing, -1) << "first differing step after the restore";
  for (BodyId id = 1; id < first.bodyCount(); ++id) {
    EXPECT_TRUE(first.isAsleep(id)) << "body " << id;
    EXPECT_EQ(first.body(id).position(), restored.body(id).position()) << "body " << id;
  }
}

}  // namespace
}  // namespace physdbg::peers
