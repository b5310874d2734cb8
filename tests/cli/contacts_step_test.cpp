// physdbg contacts --step N lists the contacts of the state after N steps,
// --max-separation D adds the pairs apart by at most D (negative depth), and
// bad values of either, or of the new scene keys, exit 2 naming them.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/visual_test_support.h"

namespace physdbg {
namespace {

using visualtesting::Result;
using visualtesting::runPhysdbg;
using visualtesting::ScratchFolder;

// A ball of radius 0.5 whose bottom is 2.5 m above a static floor (top at y = 0).
constexpr char dropScene[] = R"({"bodies": [
  {"shape": {"box": {"half_extents": [5, 0.5, 5]}}, "position": [0, -0.5, 0], "static": true},
  {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 3, 0]}]})";

nlohmann::json contactsOf(const std::string& arguments) {
  const Result run = runPhysdbg("contacts " + arguments + " --json");
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return run.exitCode == 0 ? nlohmann::json::parse(run.output) : nlohmann::json::array();
}

class ContactsStep : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(scene) << dropScene; }
  ScratchFolder folder;
  const std::string scene = folder / "drop.json";
};

TEST_F(ContactsStep, TheBallTouchesTheFloorOnlyOnceItHasFallen) {
  EXPECT_TRUE(contactsOf(scene).empty());
  // At rest it may sit a hair above the floor (within the solver's touching gap).
  const nlohmann::json landed = contactsOf(scene + " --step 120 --max-separation 0.01");
  ASSERT_EQ(landed.size(), 1u) << landed.dump();
  EXPECT_EQ(landed[0]["a"], 0);
  EXPECT_EQ(landed[0]["b"], 1);
  EXPECT_LT(std::abs(landed[0]["depth"].get<double>()), 0.01);
  EXPECT_NEAR(landed[0]["normal"][1].get<double>(), 1.0, 1e-6);
  const Result text = runPhysdbg("contacts " + scene + " --step 120 --max-separation 0.01");
  EXPECT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("1 contacts in drop after 120 steps"), std::string::npos) << text.output;
}

TEST_F(ContactsStep, MaxSeparationAddsNearPairsWithNegativeDepth) {
  const nlohmann::json near = contactsOf(scene + " --max-separation 2.6");
  ASSERT_EQ(near.size(), 1u) << near.dump();
  EXPECT_EQ(near[0]["status"], "separated");
  EXPECT_NEAR(near[0]["depth"].get<double>(), -2.5, 1e-9);
  EXPECT_TRUE(contactsOf(scene + " --max-separation 2.4").empty());
  EXPECT_TRUE(contactsOf(scene + " --max-separation 0").empty());
  // After 20 steps the ball has fallen g (20 dt)^2 / 2 = 0.545 m, more or less.
  const nlohmann::json falling = contactsOf(scene + " --step 20 --max-separation 3");
  ASSERT_EQ(falling.size(), 1u);
  EXPECT_GT(falling[0]["depth"].get<double>(), -2.5 + 0.4);
  EXPECT_LT(falling[0]["depth"].get<double>(), -2.5 + 0.7);
}

TEST_F(ContactsStep, AScheduledSetShowsAtItsStep) {
  std::ofstream(scene) << R"({"gravity": [0, 0, 0], "bodies": [
    {"shape": {"sphere": {"radius": 0.5}}, "asleep": true},
    {"shape": {"sphere": {"radius": 0.5}}, "position": [3, 0, 0]}],
    "set": [{"body": 1, "step": 2, "position": [0.5, 0, 0]}]})";
  EXPECT_TRUE(contactsOf(scene + " --step 2").empty());  // step 2 begins from here
  const nlohmann::json touching = contactsOf(scene + " --step 3");
  ASSERT_EQ(touching.size(), 1u) << touching.dump();
  EXPECT_EQ(touching[0]["status"], "penetrating");
}

TEST_F(ContactsStep, BadValuesExitTwoNamingTheOption) {
  for (const char* value : {"0", "-1", "100000001", "x", "1.5", ""}) {
    const Result run = runPhysdbg("contacts " + scene + " --step '" + value + "'");
    EXPECT_EQ(run.exitCode, 2) << value << ": " << run.output;
    EXPECT_NE(run.output.find("--step"), std::string::npos) << run.output;
  }
  for (const char* value : {"-1", "nan", "inf", "1e7", "1000000.5", "x", ""}) {
    const Result run = runPhysdbg("contacts " + scene + " --max-separation '" + value + "'");
    EXPECT_EQ(run.exitCode, 2) << value << ": " << run.output;
    EXPECT_NE(run.output.find("--max-separation"), std::string::npos) << run.output;
  }
  EXPECT_EQ(runPhysdbg("contacts " + scene + " --max-separation 1e6").exitCode, 0);
}

TEST_F(ContactsStep, TooManyNearPairsExitTwo) {
  std::ofstream(scene) << R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}},
    "repeat": {"count": [100, 1, 100], "spacing": [2, 0, 2]}}]})";  // 10,000 bodies: 5e7 pairs within 1e6 m
  const Result run = runPhysdbg("contacts " + scene + " --max-separation 1e6");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("--max-separation"), std::string::npos) << run.output;
}

TEST_F(ContactsStep, HelpNamesTheOptions) {
  const Result run = runPhysdbg("contacts --help");
  EXPECT_EQ(run.exitCode, 0);
  EXPECT_NE(run.output.find("--step N"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("--max-separation D"), std::string::npos) << run.output;
}

TEST_F(ContactsStep, BadNewSceneKeysExitTwoNamingFileAndKey) {
  struct Case {
    const char* body;
    const char* key;
  };
  for (const Case& c :
       {Case{R"("density": -2)", "bodies[0].density"}, Case{R"("inertia": [1, 1, 5])", "bodies[0].inertia"},
        Case{R"("asleep": true, "static": true)", "bodies[0].asleep"},
        Case{R"("density": 1, "mass": 1)", "bodies[0]: has both mass and density"}}) {
    std::ofstream(scene) << R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}}, )" << c.body << "}]}";
    const Result run = runPhysdbg("contacts " + scene + " --step 1");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("drop.json: " + std::string(c.key)), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace physdbg
