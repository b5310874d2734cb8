// Bodies moving on floors and ramps made of triangles against the same
// planes made of one box. A floor of coplanar triangles must give the motion
// a box floor gives, seams or not: a box sliding across them gets the same
// four corner points (mesh_contacts.h merges the triangles' manifolds), a
// ball the same single point, so the two runs agree to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/colliders/heightfield_collider.h"
#include "engine/world.h"
#include "tests/engine/meshes/mesh_test_support.h"
#include "tests/engine/test_bodies.h"

namespace physdbg {
namespace {

// The runs differ only in round-off: clipping against two triangles instead
// of one face, with clipTolerance (1e-6 m) deciding corners on a seam, moves
// a warm-start impulse by ~1e-12 and the state by ~1e-9 over seconds.
constexpr double sameMotion = 1e-8;

WorldSettings settings() {
  WorldSettings world;
  world.threads = 1;
  world.allowSleep = false;
  return world;
}

struct Trajectory {
  std::vector<RigidBody> states;  // the moving body, step by step
};

// Steps `body` over `floor` and returns its state after every step.
Trajectory run(const BodyDefinition& floor, const BodyDefinition& body, int steps) {
  World world(settings());
  world.addBody(floor);
  const BodyId id = world.addBody(body);
  Trajectory result;
  for (int step = 0; step < steps; ++step) {
    world.step();
    result.states.push_back(world.body(id));
  }
  return result;
}

double largestDifference(const Trajectory& a, const Trajectory& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    const RigidBody &p = a.states[i], &q = b.states[i];
    largest = std::max({largest, (p.position() - q.position()).cwiseAbs().maxCoeff(),
                        (p.linearVelocity() - q.linearVelocity()).cwiseAbs().maxCoeff(),
                        (p.angularVelocity() - q.angularVelocity()).cwiseAbs().maxCoeff(),
                        (p.orientation().coeffs() - q.orientation().coeffs()).cwiseAbs().maxCoeff()});
  }
  return largest;
}

BodyDefinition sliding(BodyDefinition body, const Vec3& velocity, double friction) {
  body.linearVelocity = velocity;
  body.material.staticFriction = body.material.dynamicFriction = friction;
  return body;
}

BodyDefinition withFriction(BodyDefinition body, double friction) {
  body.material.staticFriction = body.material.dynamicFriction = friction;
  return body;
}

TEST(MeshFloorMotion, SlidingBoxCrossesSeamsAsOnABoxFloor) {
  // 3 m/s at friction 0.1 slides 4.6 m: across two cells' edges and the
  // diagonals between, at an angle to both.
  const BodyDefinition box = sliding(testbodies::box(Vec3(-7.3, 0.5, 0.37)), Vec3(3, 0, 0.4), 0.1);
  const Trajectory onMesh = run(withFriction(meshtest::staticBody(meshtest::gridFloor(10, 2.0)), 0.1), box, 150);
  const Trajectory onBox = run(withFriction(testbodies::floorSlab(), 0.1), box, 150);
  EXPECT_LT(largestDifference(onMesh, onBox), sameMotion);
  double largestVy = 0.0, largestSpin = 0.0;
  for (const RigidBody& state : onMesh.states) {
    largestVy = std::max(largestVy, std::abs(state.linearVelocity().y()));
    largestSpin = std::max(largestSpin, state.angularVelocity().norm());
  }
  EXPECT_GT(onMesh.states.back().position().x(), -3.0);  // it did cross seams
  // What the box floor itself gives (the landing's first step), no more.
  double boxVy = 0.0, boxSpin = 0.0;
  for (const RigidBody& state : onBox.states) {
    boxVy = std::max(boxVy, std::abs(state.linearVelocity().y()));
    boxSpin = std::max(boxSpin, state.angularVelocity().norm());
  }
  EXPECT_LE(largestVy, boxVy + sameMotion);
  EXPECT_LE(largestSpin, boxSpin + sameMotion);
}

TEST(MeshFloorMotion, RollingBallCrossesSeamsAsOnABoxFloor) {
  BodyDefinition ball = sliding(testbodies::ball(Vec3(-7.1, 0.5, 0.3)), Vec3(4, 0, 1.5), 0.5);
  ball.angularVelocity = Vec3(0, 0, -2);  // slipping at first, then rolling
  const Trajectory onMesh = run(withFriction(meshtest::staticBody(meshtest::gridFloor(10, 2.0)), 0.5), ball, 200);
  const Trajectory onBox = run(withFriction(testbodies::floorSlab(), 0.5), ball, 200);
  EXPECT_GT(onMesh.states.back().position().x(), 0.0);
  EXPECT_LT(largestDifference(onMesh, onBox), sameMotion);
}

TEST(MeshFloorMotion, BallRollsDownATessellatedRampAsDownABox) {
  // A 20 degree ramp: the grid and a box, turned alike about z, the box's
  // top face in the grid's plane.
  const double angle = 20.0 * std::numbers::pi / 180.0;
  const Quat tilt(Eigen::AngleAxisd(-angle, Vec3::UnitZ()));
  BodyDefinition slab = testbodies::floorSlab();
  slab.orientation = tilt;
  slab.position = tilt * Vec3(0, -0.5, 0);
  const BodyDefinition grid = meshtest::staticBody(meshtest::gridFloor(10, 2.0), Vec3::Zero(), tilt);
  const BodyDefinition ball = withFriction(testbodies::ball(tilt * Vec3(-8.0, 0.5, 0.9)), 0.5);
  const Trajectory onMesh = run(withFriction(grid, 0.5), ball, 120);
  const Trajectory onBox = run(withFriction(slab, 0.5), ball, 120);
  EXPECT_GT((onMesh.states.back().position() - ball.position).norm(), 4.0);  // rolled across cells (2 m each)
  EXPECT_LT(largestDifference(onMesh, onBox), sameMotion);
  // Rolling without slipping down a slope: a = 5/7 g sin(angle).
  const double travelled = (onMesh.states.back().position() - ball.position).norm();
  const double time = 120.0 / 60.0;
  EXPECT_NEAR(travelled, 0.5 * (5.0 / 7.0) * 9.81 * std::sin(angle) * time * time, 0.02);
}

TEST(MeshFloorMotion, BoxRestsInAGullyOnBothFaces) {
  // Two slopes of 0.5 rad (29 degrees) meeting at a concave edge along z: a
  // box set into the V rests on both faces, with a manifold for each normal.
  std::vector<Vec3> vertices = {{-4, 4 * std::tan(0.5), -4}, {0, 0, -4}, {4, 4 * std::tan(0.5), -4},
                                {-4, 4 * std::tan(0.5), 4},  {0, 0, 4},  {4, 4 * std::tan(0.5), 4}};
  std::vector<MeshTriangle> triangles = {{0, 3, 1}, {1, 3, 4}, {1, 4, 2}, {2, 4, 5}};
  auto gully = std::make_shared<TriangleMeshCollider>(vertices, triangles);
  EXPECT_FALSE(gully->edgeActive(1, 2));  // the concave edge, 4 to 1 in triangle 1
  EXPECT_FALSE(gully->edgeActive(2, 0));  // and 1 to 4 in triangle 2
  World world(settings());
  world.addBody(meshtest::staticBody(gully));
  const BodyId box = world.addBody(testbodies::box(Vec3(0, 1.2, 0), 0.5));
  for (int step = 0; step < 240; ++step) world.step();
  EXPECT_LT(world.body(box).linearVelocity().norm(), 1e-3);
  EXPECT_GT(world.body(box).position().y(), 0.5);
  int manifolds = 0;
  for (const ContactManifold& manifold : world.manifolds()) manifolds += manifold.pointCount > 0 ? 1 : 0;
  EXPECT_EQ(manifolds, 2);
}

TEST(MeshFloorMotion, BallOnAGentlePeakStaysOnIt) {
  // A dome of 0.5 m cells bending by about 3 degrees an edge: every edge is
  // inactive, so each face's contact takes its face normal, and right over
  // the top vertex each face's plane passes under the ball beside its own
  // face. The ball must still land on the top, not fall through it.
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  const int cells = 16;
  std::vector<float> heights;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const double x = 0.5 * (i - cells / 2), z = 0.5 * (j - cells / 2);
      heights.push_back(static_cast<float>(-0.05 * (x * x + z * z)));
    }
  HeightfieldCollider(heights, cells + 1, cells + 1, 0.5, 0.5, 1.0).sampledGrid(cells, vertices, triangles);
  const auto dome = std::make_shared<TriangleMeshCollider>(vertices, triangles);
  EXPECT_EQ(dome->activeEdgeCount(), 4u * cells);  // only the border
  World world(settings());
  world.addBody(meshtest::staticBody(dome));
  const BodyId ball = world.addBody(testbodies::ball(Vec3(0, 3, 0)));
  double lowest = 3.0;
  for (int step = 0; step < 90; ++step) {
    world.step();
    lowest = std::min(lowest, world.body(ball).position().y());
  }
  EXPECT_GT(lowest, 0.5 - 0.02);  // at most the solver's slop into the top
}

}  // namespace
}  // namespace physdbg
