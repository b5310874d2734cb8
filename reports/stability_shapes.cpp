// Sizes and shapes far from unit boxes: 5 mm and 500 m stacks, a 1e-4 m
// thick plate and a convex mesh given duplicate and coplanar points.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "engine/colliders/convex_mesh_collider.h"
#include "reports/stability_cases.h"
#include "reports/stability_support.h"

namespace physdbg::reports {
namespace {

// Three cubes of side `size` stacked at rest on the floor. Nothing about the
// stack is scale dependent, so the largest displacement relative to the size
// must stay below 10%.
StabilityOutcome runScaledStack(double size, double seconds) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 5.0 * size));
  const double half = 0.5 * size;
  for (int i = 0; i < 3; ++i) scene.bodies.push_back(dynamicBox(Vec3(0, half + i * size, 0), Vec3(half, half, half)));
  World world = buildWorld(scene);
  const auto start = positionsOf(world);
  const int steps = static_cast<int>(std::lround(seconds / scene.world.dt));
  const int ran = runSteps(world, steps);
  StabilityOutcome outcome;
  outcome.figure = largestDisplacement(world, start) / size;
  outcome.pass = ran == steps && world.numericalFaults().empty() && outcome.figure < 0.1;
  outcome.detail = format("%.0f steps; top box moved %.3g m", ran, (world.bodies().back().position() - start.back()).norm()) +
                   faultNote(world);
  return outcome;
}

// A box `thickness` thick dropped flat from `drop` m onto the floor: it must
// come to rest on top of it, not in or under it.
StabilityOutcome runThinPlate(double thickness, int steps) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 5.0));
  scene.bodies.push_back(dynamicBox(Vec3(0, 0.5, 0), Vec3(0.5, 0.5 * thickness, 0.5)));
  World world = buildWorld(scene);
  const int ran = runSteps(world, steps);
  const double bottom = world.body(1).collider().worldBounds(world.body(1).transform()).min.y();
  StabilityOutcome outcome;
  outcome.figure = bottom;
  outcome.pass = ran == steps && world.numericalFaults().empty() && bottom > -0.01 && bottom < 0.01 &&
                 largestSpeed(world) < 0.01;
  outcome.detail = format("%.0f steps; speed at the end %.3g m/s", ran, largestSpeed(world)) + faultNote(world);
  return outcome;
}

// A unit cube given as its corners twice over, face centres and edge
// midpoints: the hull must drop them, and the body must rest like a cube.
std::vector<Vec3> degenerateCubePoints() {
  std::vector<Vec3> points;
  for (int copy = 0; copy < 2; ++copy) {
    for (int corner = 0; corner < 8; ++corner) {
      points.emplace_back(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5, corner & 4 ? 0.5 : -0.5);
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {-0.5, 0.5}) {
      Vec3 centre = Vec3::Zero();
      centre[axis] = side;
      points.push_back(centre);
      for (const double along : {-0.5, 0.5}) {
        Vec3 midpoint = centre;
        midpoint[(axis + 1) % 3] = along;
        points.push_back(midpoint);
      }
    }
  }
  return points;
}

StabilityOutcome runDegenerateMesh(int steps) {
  SceneDescription scene;
  scene.bodies.push_back(floorAt(Vec3::Zero(), 0.0, 5.0));
  BodyDefinition mesh;
  const auto collider = std::make_shared<ConvexMeshCollider>(degenerateCubePoints());
  mesh.collider = collider;
  mesh.position = Vec3(0, 1.5, 0);
  mesh.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3(0, 0, 1)));
  scene.bodies.push_back(mesh);
  World world = buildWorld(scene);
  const int ran = runSteps(world, steps);
  const double bottom = world.body(1).collider().worldBounds(world.body(1).transform()).min.y();
  StabilityOutcome outcome;
  outcome.figure = bottom;
  outcome.pass = ran == steps && world.numericalFaults().empty() && collider->hullVertices().size() == 8 &&
                 std::abs(bottom) < 0.01 && largestSpeed(world) < 0.01;
  outcome.detail = format("%.0f steps; hull kept %.0f of %.0f points", ran,
                          static_cast<double>(collider->hullVertices().size()),
                          static_cast<double>(degenerateCubePoints().size())) +
                   format("; speed at the end %.3g m/s", largestSpeed(world)) + faultNote(world);
  return outcome;
}

}  // namespace

std::vector<StabilityCase> shapeCases() {
  return {
      {"tiny_bodies", "three 5 mm cubes stacked: largest displacement < 10% of their size", "size",
       [](RunLength length) { return runScaledStack(0.005, length == RunLength::Test ? 1.0 : 4.0); }},
      {"huge_bodies", "three 500 m cubes stacked: largest displacement < 10% of their size", "size",
       [](RunLength length) { return runScaledStack(500.0, length == RunLength::Test ? 1.0 : 4.0); }},
      {"thin_plate", "1e-4 m thick box dropped 0.5 m rests on the floor: bottom within 0.01 m of it, speed < 0.01 m/s",
       "m", [](RunLength length) { return runThinPlate(1e-4, length == RunLength::Test ? 120 : 300); }},
      {"degenerate_mesh",
       "cube mesh with duplicate and coplanar points: hull has 8 vertices, rests within 0.01 m of the floor", "m",
       [](RunLength length) { return runDegenerateMesh(length == RunLength::Test ? 180 : 600); }},
  };
}

}  // namespace physdbg::reports
