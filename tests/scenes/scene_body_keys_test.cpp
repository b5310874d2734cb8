// The scene keys ports of other engines' tests need: "asleep", "density",
// "inertia" on a body and the top-level "set" list. Each valid form gives the
// body or the run it says; each hostile value is a SceneError naming the file
// and the key.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

constexpr char floorJson[] = R"({"shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0],
                                 "static": true})";

// A scene of the given body entries (and top-level extras), file keys.json.
SceneDescription sceneOf(const std::string& bodies, const std::string& extra = "") {
  return parseScene(R"({"bodies": [)" + bodies + "]" + extra + "}", "keys.json");
}

World worldOf(const std::string& bodies, const std::string& extra = "") { return buildWorld(sceneOf(bodies, extra)); }

// The message of the SceneError that loading and building the scene raises,
// or "" when it loads.
std::string refusal(const std::string& bodies, const std::string& extra = "") {
  try {
    worldOf(bodies, extra);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

void expectRefused(const std::string& bodies, const std::string& extra, const std::vector<std::string>& mentions) {
  const std::string message = refusal(bodies, extra);
  ASSERT_FALSE(message.empty()) << bodies << extra;
  EXPECT_EQ(message.rfind("keys.json: ", 0), 0u) << message;
  for (const std::string& part : mentions) EXPECT_NE(message.find(part), std::string::npos) << message;
}

// --- asleep ---------------------------------------------------------------

TEST(SceneAsleep, ABodyStartsAsleepAndStaysWhereItIs) {
  World world = worldOf(std::string(floorJson) + R"(, {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}},
      "position": [0, 3, 0], "asleep": true})");
  ASSERT_TRUE(world.isAsleep(1));
  for (int step = 0; step < 120; ++step) world.step();
  EXPECT_TRUE(world.isAsleep(1));
  EXPECT_EQ(world.body(1).position(), Vec3(0, 3, 0));  // no gravity while asleep
  EXPECT_EQ(world.lastStepStats().sleepingBodies, 1);
}

TEST(SceneAsleep, FalseAndEveryRepeatedCopy) {
  EXPECT_FALSE(worldOf(R"({"shape": {"sphere": {"radius": 1}}, "asleep": false})").isAsleep(0));
  const World world = worldOf(R"({"shape": {"sphere": {"radius": 0.5}}, "asleep": true,
      "repeat": {"count": [3, 1, 1], "spacing": [2, 0, 0]}})");
  for (BodyId id = 0; id < 3; ++id) EXPECT_TRUE(world.isAsleep(id)) << id;
}

TEST(SceneAsleep, AFallingBallWakesTheSleeperItLandsOn) {
  World world = worldOf(std::string(floorJson) + R"(, {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}},
      "position": [0, 0.5, 0], "asleep": true}, {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 3, 0]})");
  bool woke = false;
  for (int step = 0; step < 90 && !woke; ++step) {
    world.step();
    woke = !world.isAsleep(1);
  }
  EXPECT_TRUE(woke);
  EXPECT_GT(world.body(2).position().y(), 1.3);  // it landed on the box, not through it
}

TEST(SceneAsleep, AForceWakesIt) {
  World world = worldOf(R"({"shape": {"sphere": {"radius": 0.5}}, "asleep": true})",
                        R"(, "gravity": [0, 0, 0], "forces": [{"body": 0, "force": [2, 0, 0],
                           "mode": "velocity_change", "steps": [5, 6]}])");
  for (int step = 0; step < 5; ++step) world.step();
  EXPECT_TRUE(world.isAsleep(0));
  world.step();
  EXPECT_FALSE(world.isAsleep(0));
  EXPECT_EQ(world.body(0).linearVelocity().x(), 2.0);
}

TEST(SceneAsleep, HostileValuesNameTheKey) {
  const std::string ball = R"({"shape": {"sphere": {"radius": 1}}, )";
  expectRefused(ball + R"("asleep": true, "static": true})", "", {"bodies[0].asleep", "static"});
  expectRefused(ball + R"("asleep": true, "kinematic": true})", "", {"bodies[0].asleep", "kinematic"});
  expectRefused(ball + R"("asleep": "yes"})", "", {"bodies[0].asleep", "true or false"});
  expectRefused(ball + R"("asleep": 1})", "", {"bodies[0].asleep"});
  expectRefused(ball + R"("asleep": true, "velocity": [0, 1, 0]})", "", {"bodies[0].asleep", "velocity"});
  expectRefused(ball + R"("asleep": true, "angular_velocity": [0, 1, 0]})", "", {"bodies[0].asleep"});
  expectRefused(ball + R"("asleep": true, "add_at_step": 5})", "", {"bodies[0].asleep", "add_at_step"});
  EXPECT_EQ(refusal(ball + R"("asleep": true, "add_at_step": 0, "remove_at_step": 9})"), "");
}

// --- density --------------------------------------------------------------

TEST(SceneDensity, MassIsDensityTimesTheShapesVolume) {
  EXPECT_DOUBLE_EQ(worldOf(R"({"shape": {"box": {"half_extents": [0.5, 1, 2]}}, "density": 3})").body(0).mass(),
                   3.0 * 4.0 * 0.5 * 1 * 2 * 2);
  EXPECT_DOUBLE_EQ(worldOf(R"({"shape": {"sphere": {"radius": 2}}, "density": 1000})").body(0).mass(),
                   1000.0 * 4.0 / 3.0 * std::numbers::pi * 8.0);
  // The inertia follows the mass, as with "mass".
  const World dense = worldOf(R"({"shape": {"sphere": {"radius": 1}}, "density": 6})");
  EXPECT_NEAR(dense.body(0).localInertia()(0, 0), 0.4 * dense.body(0).mass(), 1e-12);
  // A static body ignores it, as it ignores a mass.
  EXPECT_EQ(worldOf(R"({"shape": {"sphere": {"radius": 1}}, "density": 5, "static": true})").body(0).mass(), 0.0);
}

TEST(SceneDensity, HostileValuesNameTheKey) {
  const std::string box = R"({"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, )";
  expectRefused(box + R"("density": 2, "mass": 1})", "", {"bodies[0]", "mass", "density"});
  expectRefused(box + R"("density": 0})", "", {"bodies[0].density", "positive"});
  expectRefused(box + R"("density": -1000})", "", {"bodies[0].density"});
  expectRefused(box + R"("density": "dense"})", "", {"bodies[0].density", "number"});
  expectRefused(box + R"("density": 1e10})", "", {"bodies[0].density", "1e+09"});
  expectRefused(box + R"("density": 1, "kinematic": true})", "", {"bodies[0].density", "kinematic"});
  // Within its own bounds but past the mass's: 1e9 kg/m^3 over 8e6 m^3.
  expectRefused(R"({"shape": {"box": {"half_extents": [100, 100, 100]}}, "density": 1e9})", "",
                {"bodies[0].density", "gives a mass of 8e+15 kg"});
  expectRefused(R"({"shape": {"sphere": {"radius": 1e-3}}, "density": 1e-9})", "", {"bodies[0].density", "mass"});
  const std::string huge = "1" + std::string(400, '0');
  EXPECT_NE(refusal(box + R"("density": )" + huge + "}").find("keys.json"), std::string::npos);
}

// --- inertia --------------------------------------------------------------

TEST(SceneInertia, PrincipalMomentsReplaceTheShapes) {
  const World world = worldOf(R"({"shape": {"sphere": {"radius": 0.5}}, "mass": 2, "inertia": [1, 2, 2.5]})");
  EXPECT_EQ(world.body(0).localInertia(), Vec3(1, 2, 2.5).asDiagonal().toDenseMatrix());
  EXPECT_EQ(world.body(0).mass(), 2.0);
}

TEST(SceneInertia, AFullTensorIsTakenAsGiven) {
  const World world = worldOf(R"({"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}},
      "inertia": [[2, 0.1, 0], [0.1, 2, -0.2], [0, -0.2, 3]]})");
  Mat3 expected;
  expected << 2, 0.1, 0, 0.1, 2, -0.2, 0, -0.2, 3;
  EXPECT_EQ(world.body(0).localInertia(), expected);
  // Asymmetric within a relative 1e-9 is symmetric enough (and made exact).
  const World close = worldOf(R"({"shape": {"sphere": {"radius": 1}},
      "inertia": [[1, 1e-12, 0], [0, 1, 0], [0, 0, 1]]})");
  EXPECT_EQ(close.body(0).localInertia()(0, 1), close.body(0).localInertia()(1, 0));
  // A flat plate meets the triangle inequality with equality.
  EXPECT_EQ(refusal(R"({"shape": {"sphere": {"radius": 1}}, "inertia": [1, 1, 2]})"), "");
}

// An angular impulse L turns the body at I^-1 L: with the tensor given, not the sphere's 0.4 m r^2.
TEST(SceneInertia, TheGivenTensorTurnsTheBody) {
  World world = worldOf(R"({"shape": {"sphere": {"radius": 0.5}}, "inertia": [1, 4, 4]})",
                        R"(, "gravity": [0, 0, 0], "forces": [{"body": 0, "torque": [0, 2, 0], "mode": "impulse"}])");
  world.step();
  EXPECT_NEAR(world.body(0).angularVelocity().y(), 0.5, 1e-12);
}

TEST(SceneInertia, HostileValuesNameTheKey) {
  const std::string ball = R"({"shape": {"sphere": {"radius": 1}}, "inertia": )";
  const auto refused = [&](const std::string& inertia, const std::vector<std::string>& mentions) {
    expectRefused(ball + inertia + "}", "", mentions);
  };
  refused("[1, 2]", {"bodies[0].inertia", "3 elements"});
  refused("[1, 2, 2, 2]", {"bodies[0].inertia", "3 elements"});
  refused("[0, 1, 1]", {"bodies[0].inertia[0]", "positive"});
  refused("[1, -1, 1]", {"bodies[0].inertia[1]", "positive"});
  refused("[1, 1, 3]", {"bodies[0].inertia", "triangle inequality"});
  refused("[1, 1e10, 1]", {"bodies[0].inertia[1]", "1e+09"});
  refused("[1, \"x\", 1]", {"bodies[0].inertia[1]", "number"});
  refused("[1, [1, 0, 0], 1]", {"bodies[0].inertia[1]", "number"});
  refused("\"diagonal\"", {"bodies[0].inertia", "array"});
  refused("[[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]", {"bodies[0].inertia", "not symmetric"});
  refused("[[1, 2, 0], [2, 1, 0], [0, 0, 1]]", {"bodies[0].inertia", "not positive definite"});
  refused("[[1, 0, 0], [0, 0, 0], [0, 0, 1]]", {"bodies[0].inertia", "not positive definite"});
  refused("[[1, 0, 0], [0, 1, 0]]", {"bodies[0].inertia", "3 elements"});
  refused("[[1, 0, 0], [0, 1], [0, 0, 1]]", {"bodies[0].inertia[1]", "3 elements"});
  refused("[[1, 0, 0], 1, [0, 0, 1]]", {"bodies[0].inertia[1]", "array"});
  refused("[[1, 0, 0], [0, 1, 0], [0, 0, 1e999]]", {"keys.json"});
  refused("[[1, 0, 0], [0, 1, 0], [0, 0, 3]]", {"bodies[0].inertia", "triangle inequality"});
  expectRefused(R"({"shape": {"sphere": {"radius": 1}}, "static": true, "inertia": [1, 1, 1]})", "",
                {"bodies[0].inertia", "static"});
  expectRefused(R"({"shape": {"sphere": {"radius": 1}}, "kinematic": true, "inertia": [1, 1, 1]})", "",
                {"bodies[0].inertia", "kinematic"});
}

// --- set ------------------------------------------------------------------

// A unit sphere, gravity off, with the given "set" entries.
World worldWithSet(const std::string& set, const std::string& body = R"({"shape": {"sphere": {"radius": 0.5}}})") {
  return worldOf(body + R"(, {"shape": {"sphere": {"radius": 0.5}}, "position": [0, -9, 0], "static": true})",
                 R"(, "gravity": [0, 0, 0], "allow_sleep": false, "set": [)" + set + "]");
}

TEST(SceneSet, AVelocityTakesOverWhenItsStepBegins) {
  World world = worldWithSet(R"({"body": 0, "step": 5, "velocity": [1, 0, 0]})");
  for (int step = 0; step < 5; ++step) world.step();
  EXPECT_EQ(world.body(0).linearVelocity(), Vec3::Zero());  // the world after 5 steps is replaced as step 5 begins
  world.step();
  EXPECT_EQ(world.body(0).linearVelocity(), Vec3(1, 0, 0));
  EXPECT_NEAR(world.body(0).position().x(), world.settings().dt, 1e-15);
}

TEST(SceneSet, EachPartReplacesTheBodysOwn) {
  World world = worldWithSet(R"({"body": 0, "step": 0, "position": [4, 5, 6], "orientation": [0, 0, 2, 0]},
                                {"body": 0, "step": 2, "angular_velocity": [0, 0, 3]})");
  world.step();
  EXPECT_EQ(world.body(0).position(), Vec3(4, 5, 6));
  EXPECT_NEAR(std::abs(world.body(0).orientation().y()), 1.0, 1e-15);  // normalised
  world.step();
  world.step();
  EXPECT_EQ(world.body(0).angularVelocity(), Vec3(0, 0, 3));
  EXPECT_EQ(world.body(0).position(), Vec3(4, 5, 6));
}

TEST(SceneSet, TheLaterOfTwoChangesWinsAndAKinematicBodyMayBeSet) {
  World world = worldWithSet(R"({"body": 0, "step": 1, "velocity": [1, 0, 0]},
                                {"body": 0, "step": 1, "velocity": [0, 2, 0]})",
                             R"({"shape": {"sphere": {"radius": 0.5}}, "kinematic": true})");
  for (int step = 0; step < 11; ++step) world.step();
  EXPECT_EQ(world.body(0).linearVelocity(), Vec3(0, 2, 0));
  EXPECT_NEAR(world.body(0).position().y(), 20 * world.settings().dt, 1e-12);
}

TEST(SceneSet, ASleepingBodyThatIsSetWakes) {
  World world = worldWithSet(R"({"body": 0, "step": 3, "position": [0, 2, 0]})",
                             R"({"shape": {"sphere": {"radius": 0.5}}, "asleep": true})");
  for (int step = 0; step < 3; ++step) world.step();
  EXPECT_TRUE(world.isAsleep(0));
  world.step();
  EXPECT_FALSE(world.isAsleep(0));
  EXPECT_EQ(world.body(0).position(), Vec3(0, 2, 0));
}

TEST(SceneSet, HostileEntriesNameTheirKey) {
  const auto refused = [](const std::string& set, const std::vector<std::string>& mentions) {
    expectRefused(R"({"shape": {"sphere": {"radius": 1}}}, {"shape": {"sphere": {"radius": 1}}, "static": true,
                    "position": [5, 0, 0]})",
                  R"(, "set": )" + set, mentions);
  };
  refused(R"({"body": 0})", {"set", "array"});
  refused(R"([3])", {"set[0]", "object"});
  refused(R"([{"step": 0, "velocity": [1, 0, 0]}])", {"set[0]", "body"});
  refused(R"([{"body": 2, "step": 0, "velocity": [1, 0, 0]}])", {"set[0].body"});
  refused(R"([{"body": -1, "step": 0, "velocity": [1, 0, 0]}])", {"set[0].body"});
  refused(R"([{"body": 1, "step": 0, "velocity": [1, 0, 0]}])", {"set[0].body", "static"});
  refused(R"([{"body": 0, "velocity": [1, 0, 0]}])", {"set[0]", "step"});
  refused(R"([{"body": 0, "step": -1, "velocity": [1, 0, 0]}])", {"set[0].step"});
  refused(R"([{"body": 0, "step": 10000000, "velocity": [1, 0, 0]}])", {"set[0].step", "9999999"});
  refused(R"([{"body": 0, "step": 1.5, "velocity": [1, 0, 0]}])", {"set[0].step"});
  refused(R"([{"body": 0, "step": 0}])", {"set[0]", "at least one"});
  refused(R"([{"body": 0, "step": 0, "mass": 2}])", {"set[0].mass", "unknown key"});
  refused(R"([{"body": 0, "step": 0, "position": [1, 0]}])", {"set[0].position", "3 elements"});
  refused(R"([{"body": 0, "step": 0, "position": [1e10, 0, 0]}])", {"set[0].position[0]"});
  refused(R"([{"body": 0, "step": 0, "velocity": [0, "fast", 0]}])", {"set[0].velocity[1]"});
  refused(R"([{"body": 0, "step": 0, "angular_velocity": [0, 0, 1e999]}])", {"keys.json"});
  refused(R"([{"body": 0, "step": 0, "orientation": [0, 0, 0, 0]}])", {"set[0].orientation", "zero"});
  refused(R"([{"body": 0, "step": 0, "orientation": [1, 0, 0]}])", {"set[0].orientation", "4 elements"});
  std::string many = "[";
  for (int i = 0; i <= 10'000; ++i)
    many += std::string(i ? "," : "") + R"({"body": 0, "step": 0, "velocity": [1, 0, 0]})";
  refused(many + "]", {"set", "10001 entries", "at most 10000"});
}

}  // namespace
}  // namespace physdbg

namespace physdbg {
namespace {

// "time_of_impact": on by default, off when false; anything but a bool is
// refused naming the key.
TEST(SceneTimeOfImpact, DefaultsOnAndTurnsOffAndRefusesOtherTypes) {
  const auto load = [](const std::string& extra) {
    return parseScene(std::string(R"({"bodies": [{"shape": {"sphere": {"radius": 1}}}])") + extra + "}", "toi.json");
  };
  EXPECT_TRUE(load("").world.castFastPairs);
  EXPECT_FALSE(load(R"(, "time_of_impact": false)").world.castFastPairs);
  try {
    load(R"(, "time_of_impact": 1)");
    ADD_FAILURE() << "a number was taken for time_of_impact";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("toi.json"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("time_of_impact"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace physdbg
