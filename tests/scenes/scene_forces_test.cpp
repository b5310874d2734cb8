// Forces from scene files: each ForceMode on a 2 kg body with gravity off
// gives the exact velocity the mode's definition says, a force off the
// centre spins the body with torque r x F, and bad entries name their key.
#include <gtest/gtest.h>

#include <string>

#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

// A 2 kg unit sphere at the origin, gravity off, and one force entry.
World worldWithForce(const std::string& force) {
  const std::string text = R"({"gravity": [0, 0, 0], "allow_sleep": false, "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}, "mass": 2}], "forces": [)" +
                           force + "]}";
  return buildWorld(parseScene(text, "forces.json"));
}

double speedAfter(const std::string& force, int steps) {
  World world = worldWithForce(force);
  for (int i = 0; i < steps; ++i) world.step();
  return world.body(0).linearVelocity().x();
}

TEST(SceneForces, EachModeGivesTheExactVelocity) {
  // 10 N on 2 kg for 60 steps of 1/60 s: a = 5 m/s^2 for 1 s.
  EXPECT_NEAR(speedAfter(R"({"body": 0, "force": [10, 0, 0], "steps": [0, 60]})", 90), 5.0, 1e-12);
  EXPECT_NEAR(speedAfter(R"({"body": 0, "force": [10, 0, 0], "mode": "acceleration", "steps": [0, 60]})", 90), 10.0,
              1e-12);
  // Once (the default steps [0, 1]): 4 N s on 2 kg, and 3 m/s whatever the mass.
  EXPECT_NEAR(speedAfter(R"({"body": 0, "force": [4, 0, 0], "mode": "impulse"})", 30), 2.0, 1e-12);
  EXPECT_NEAR(speedAfter(R"({"body": 0, "force": [3, 0, 0], "mode": "velocity_change"})", 30), 3.0, 1e-12);
}

TEST(SceneForces, StepsRangeIsHalfOpen) {
  World world = worldWithForce(R"({"body": 0, "force": [0, 0, 2], "mode": "velocity_change", "steps": [3, 5]})");
  for (int step = 0; step < 8; ++step) {
    world.step();
    const double expected = step < 3 ? 0.0 : step < 5 ? 2.0 * (step - 2) : 4.0;
    EXPECT_EQ(world.body(0).linearVelocity().z(), expected) << "after step " << step;
  }
}

// An impulse J at r from the centre: linear J / m, angular I^-1 (r x J).
// Sphere: I = 2/5 m r^2 = 0.2 kg m^2.
TEST(SceneForces, OffCentreForceSpinsTheBodyWithRCrossF) {
  World world = worldWithForce(R"({"body": 0, "force": [0, 4, 0], "mode": "impulse", "at": [0.5, 0, 0]})");
  world.step();
  EXPECT_NEAR(world.body(0).linearVelocity().y(), 2.0, 1e-12);
  EXPECT_NEAR(world.body(0).angularVelocity().z(), 0.5 * 4.0 / 0.2, 1e-12);
  EXPECT_NEAR(world.body(0).angularVelocity().x(), 0.0, 1e-12);
}

TEST(SceneForces, TorqueTurnsTheBody) {
  World world = worldWithForce(R"({"body": 0, "torque": [0, 1, 0], "mode": "impulse"})");
  world.step();
  EXPECT_NEAR(world.body(0).angularVelocity().y(), 1.0 / 0.2, 1e-12);
  EXPECT_EQ(world.body(0).linearVelocity(), Vec3::Zero());
}

TEST(SceneForces, BadEntriesNameTheirKey) {
  struct Case {
    std::string forces, mentions;
  };
  const std::string bodies = R"("bodies": [{"shape": {"sphere": {"radius": 1}}},
      {"shape": {"sphere": {"radius": 1}}, "position": [5, 0, 0], "static": true}])";
  for (const Case& c : {Case{R"([{"body": 2, "force": [1, 0, 0]}])", "forces[0].body"},
                        Case{R"([{"body": 1, "force": [1, 0, 0]}])", "static"},
                        Case{R"([{"body": -1, "force": [1, 0, 0]}])", "forces[0].body"},
                        Case{R"([{"body": 0}])", "exactly one of force and torque"},
                        Case{R"([{"body": 0, "force": [1, 0, 0], "torque": [1, 0, 0]}])", "exactly one"},
                        Case{R"([{"body": 0, "torque": [1, 0, 0], "at": [0, 0, 0]}])", "forces[0].at"},
                        Case{R"([{"body": 0, "force": [1, 0, 0], "mode": "shove"}])", "forces[0].mode"},
                        Case{R"([{"body": 0, "force": [1, 0, 0], "steps": [4, 4]}])", "forces[0].steps[1]"},
                        Case{R"([{"body": 0, "force": [1, 0, 0], "steps": [0]}])", "forces[0].steps"},
                        Case{R"([{"body": 0, "force": [1e999, 0, 0]}])", "overflow"},
                        Case{R"({"body": 0})", "forces"}}) {
    try {
      parseScene("{" + bodies + R"(, "forces": )" + c.forces + "}", "bad.json");
      ADD_FAILURE() << "accepted " << c.forces;
    } catch (const SceneError& error) {
      EXPECT_NE(std::string(error.what()).find(c.mentions), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("bad.json"), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace physdbg
