// The design's scenes. Positions and velocities come from fixed formulas of
// the ball index, so every run builds the same world.
#include "scenes/design_scenes.h"

#include <cmath>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/solver/solver_settings.h"
#include "scenes/body_builders.h"

namespace physdbg {
namespace {

constexpr double ballRadius = 0.5;
constexpr double innerHalfWidth = 4.0;  // balls move in [-4, 4] x [-4, 4]
constexpr double wallHalfHeight = 4.0;  // walls stand from y = 0 to y = 8

// Floor, four walls and a tilted second ground. The walls overlap the floor
// and each other at the corners: those static-static overlaps are what the
// design's static-pair skipping saves.
void addEnclosure(SceneDescription& scene) {
  const double wall = innerHalfWidth + 0.5;
  scene.bodies.push_back(staticBox(Vec3(0, -0.5, 0), Vec3(wall + 0.5, 0.5, wall + 0.5)));
  scene.bodies.push_back(staticBox(Vec3(wall, wallHalfHeight, 0), Vec3(0.5, wallHalfHeight, wall + 0.5)));
  scene.bodies.push_back(staticBox(Vec3(-wall, wallHalfHeight, 0), Vec3(0.5, wallHalfHeight, wall + 0.5)));
  scene.bodies.push_back(staticBox(Vec3(0, wallHalfHeight, wall), Vec3(wall + 0.5, wallHalfHeight, 0.5)));
  scene.bodies.push_back(staticBox(Vec3(0, wallHalfHeight, -wall), Vec3(wall + 0.5, wallHalfHeight, 0.5)));
  // A ramp leaning on the -x wall: a second ground at another height.
  scene.bodies.push_back(staticBox(Vec3(-2.6, 1.0, 0), Vec3(1.6, 0.1, 2.0), Quat(Eigen::AngleAxisd(-0.35, Vec3::UnitZ()))));
}

// Balls on a 4 x 4 grid per layer, 1.8 m apart, layers 1.5 m apart from
// y = 3 upwards, each thrown sideways so they keep meeting each other.
BodyDefinition ball(int index) {
  const int layer = index / 16, row = (index / 4) % 4, column = index % 4;
  BodyDefinition body;
  body.collider = std::make_shared<SphereCollider>(ballRadius);
  body.position = Vec3(-2.7 + 1.8 * column, 3.0 + 1.5 * layer, -2.7 + 1.8 * row);
  body.linearVelocity = Vec3(3.0 * std::sin(1.7 * index), 1.0 * std::cos(0.9 * index), 3.0 * std::cos(1.3 * index));
  body.material.restitution = 0.5 + 0.1 * (index % 4);  // 0.5 .. 0.8
  return body;
}

SceneDescription ballsScene(const std::string& name, const std::string& description, int count,
                            BroadPhaseKind broadPhase, bool skipStaticPairs) {
  SceneDescription scene;
  scene.name = name;
  scene.description = description;
  scene.steps = 600;
  scene.world.broadPhase = broadPhase;
  scene.world.bruteForceBothOrders = broadPhase == BroadPhaseKind::BruteForce;  // the design's A-B and B-A
  scene.world.skipStaticPairs = skipStaticPairs;
  scene.world.allowSleep = false;  // the design had no sleeping: every step does the full work
  scene.world.solver.kind = SolverKind::Seed;  // the design's response, not our sequential impulses
  addEnclosure(scene);
  for (int i = 0; i < count; ++i) scene.bodies.push_back(ball(i));
  SceneCamera camera;
  // Steep enough to see the floor over the 8 m near wall.
  camera.eye = Vec3(0, 24, 8);
  camera.target = Vec3(0, 1, 0);
  scene.camera = camera;
  return scene;
}

// Four spheres side by side, restitution 0, 0.5, 0.8 and 1, dropped from
// 4 m onto a floor of restitution 0 (the design's response averages the
// pair's values).
SceneDescription bounceScene(const std::string& description) {
  SceneDescription scene;
  scene.name = "bounce";
  scene.description = description;
  scene.steps = 300;
  scene.world.solver.kind = SolverKind::Seed;  // the design's response
  scene.bodies.push_back(staticBox(Vec3(0, -0.5, 0), Vec3(4, 0.5, 2)));
  const double restitutions[] = {0.0, 0.5, 0.8, 1.0};
  for (int i = 0; i < 4; ++i) {
    BodyDefinition body;
    body.collider = std::make_shared<SphereCollider>(ballRadius);
    body.position = Vec3(-2.25 + 1.5 * i, 4.0 + ballRadius, 0);
    body.material.restitution = restitutions[i];
    scene.bodies.push_back(body);
  }
  SceneCamera camera;
  camera.eye = Vec3(0, 2.5, 9);
  camera.target = Vec3(0, 2, 0);
  scene.camera = camera;
  return scene;
}

BuiltinScene ballsEntry(const std::string& name, const std::string& description, int count,
                        BroadPhaseKind broadPhase, bool skipStaticPairs) {
  return {name, description, [=] { return ballsScene(name, description, count, broadPhase, skipStaticPairs); }};
}

}  // namespace

std::vector<BuiltinScene> designScenes() {
  const std::string bounceDescription =
      "spheres of restitution 0, 0.5, 0.8, 1 dropped side by side onto a floor of 0 (design's seed response: "
      "restitutions average, so each bounces with e/2)";
  return {
      ballsEntry("balls24", "24 balls bouncing in an enclosure with a floor, walls and a ramp (tree, design's seed response)", 24,
                 BroadPhaseKind::Tree, true),
      ballsEntry("balls48", "48 balls bouncing in an enclosure with a floor, walls and a ramp (tree, design's seed response)", 48,
                 BroadPhaseKind::Tree, true),
      ballsEntry("balls48_bruteforce", "balls48 with brute-force pairs, each tested as A-B and B-A (seed response)", 48,
                 BroadPhaseKind::BruteForce, true),
      ballsEntry("balls48_no_static_skip", "balls48 (tree) with static-static pairs tested too (seed response)", 48,
                 BroadPhaseKind::Tree, false),
      ballsEntry("balls48_bruteforce_no_static_skip", "balls48_bruteforce with static-static pairs tested too (seed response)", 48,
                 BroadPhaseKind::BruteForce, false),
      {"bounce", bounceDescription, [=] { return bounceScene(bounceDescription); }},
  };
}

}  // namespace physdbg
