// "add_at_step" and "remove_at_step" in scene files: every copy of a
// repeated body gets the lifetime, the world follows it, and bad values name
// their key.
#include <gtest/gtest.h>

#include <string>

#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

SceneDescription sceneWithBody(const std::string& keys) {
  const std::string text = R"({"gravity": [0, 0, 0], "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [3, 0, 0], )" +
                           keys + "}]}";
  return parseScene(text, "arrivals.json");
}

TEST(SceneLifetimes, RepeatedBodiesAllArriveAndLeave) {
  const SceneDescription scene =
      sceneWithBody(R"("add_at_step": 2, "remove_at_step": 4, "repeat": {"count": [3, 1, 1], "spacing": [2, 0, 0]})");
  ASSERT_EQ(scene.bodies.size(), 4u);
  ASSERT_EQ(scene.lifetimes.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(scene.lifetimes[i].body, i + 1);
    EXPECT_EQ(scene.lifetimes[i].addAtStep, 2);
    EXPECT_EQ(scene.lifetimes[i].removeAtStep, 4);
  }
  World world = buildWorld(scene);
  for (int state = 0; state <= 5; ++state) {
    for (BodyId id = 1; id < 4; ++id) EXPECT_EQ(world.isPresent(id), state >= 2 && state < 4) << "state " << state;
    EXPECT_TRUE(world.isPresent(0));
    world.step();
  }
}

TEST(SceneLifetimes, RemoveOnlyKeepsTheBodyFromTheStart) {
  World world = buildWorld(sceneWithBody(R"("remove_at_step": 1)"));
  EXPECT_TRUE(world.isPresent(1));
  world.step();
  EXPECT_FALSE(world.isPresent(1));
}

TEST(SceneLifetimes, BadValuesNameTheirKey) {
  const auto message = [](const std::string& keys) {
    try {
      sceneWithBody(keys);
    } catch (const SceneError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"("add_at_step": -1)").find("bodies[1].add_at_step"), std::string::npos);
  EXPECT_NE(message(R"("add_at_step": 1.5)").find("bodies[1].add_at_step"), std::string::npos);
  EXPECT_NE(message(R"("add_at_step": 5, "remove_at_step": 5)").find("bodies[1].remove_at_step"), std::string::npos);
  EXPECT_NE(message(R"("remove_at_step": 0)").find("bodies[1].remove_at_step"), std::string::npos);
  EXPECT_NE(message(R"("add_at_step": 99999999999)").find("bodies[1].add_at_step"), std::string::npos);
}

}  // namespace
}  // namespace physdbg
