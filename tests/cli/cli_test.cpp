// End-to-end tests of the physdbg command: exit codes, messages, outputs.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "render/image.h"
#include "tests/support/visual_test_support.h"

namespace {

namespace fs = std::filesystem;

using physdbg::visualtesting::Result;

Result run(const std::string& arguments) { return physdbg::visualtesting::runPhysdbg(arguments); }

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() / ("physdbg-cli-test-" + std::to_string(::getpid()) + "-" +
                                         ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  std::string file(const std::string& name, const std::string& content = "") const {
    const fs::path path = path_ / name;
    if (!content.empty()) std::ofstream(path) << content;
    return path.string();
  }
  std::string path() const { return path_.string(); }

 private:
  fs::path path_;
};

TEST(Cli, HelpExitsZeroForEveryCommand) {
  for (const char* command : {"--help", "scenes --help", "simulate --help", "render --help", "bench --help"}) {
    const Result result = run(command);
    EXPECT_EQ(result.exitCode, 0) << command << "\n" << result.output;
    EXPECT_NE(result.output.find("usage: physdbg"), std::string::npos) << command;
  }
}

TEST(Cli, BadUsageExitsTwoWithAMessage) {
  struct Case {
    const char* arguments;
    const char* mentions;
  };
  for (const Case& c :
       {Case{"frobnicate", "unknown command"}, Case{"", "usage"}, Case{"render default --sizes 10x10", "--sizes"},
        Case{"render default --size 12", "--size"}, Case{"render default --frames -3", "--frames"},
        Case{"render default --layers shapes,glow", "glow"}, Case{"simulate", "missing argument"},
        Case{"simulate default --steps zero", "--steps"}, Case{"simulate no_such_scene", "no_such_scene"},
        Case{"bench no_such_bench", "no_such_bench"}, Case{"render default -o /dev/null/frames", "/dev/null/frames"},
        Case{"simulate bounce --solver impulses", "--solver"},
        Case{"bench pyramid --quick --solver impulses", "--solver"}, Case{"bench seed --quick --repeat 0", "--repeat"},
        Case{"bench seed --quick --repeat 21", "--repeat"}}) {
    const Result result = run(c.arguments);
    EXPECT_EQ(result.exitCode, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << c.arguments << "\n" << result.output;
  }
}

// --repeat N runs the benchmarks N times and prints one record per case:
// the median run's, with every run's ratio.
TEST(Cli, BenchRepeatPrintsOneRecordPerCaseWithEveryRunsRatio) {
  const Result once = run("bench seed --quick --json");
  const Result thrice = run("bench seed --quick --json --repeat 3");
  ASSERT_EQ(once.exitCode, 0) << once.output;
  ASSERT_EQ(thrice.exitCode, 0) << thrice.output;
  const auto records = [](const std::string& output) {
    std::vector<nlohmann::json> result;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
      if (!line.empty() && line[0] == '{') result.push_back(nlohmann::json::parse(line));
    return result;
  };
  const std::vector<nlohmann::json> single = records(once.output), repeated = records(thrice.output);
  ASSERT_FALSE(single.empty());
  ASSERT_EQ(repeated.size(), single.size());
  for (std::size_t i = 0; i < single.size(); ++i) {
    EXPECT_EQ(repeated[i]["name"], single[i]["name"]);
    EXPECT_EQ(repeated[i]["repeats"], 3);
    ASSERT_EQ(repeated[i]["ours_ms_runs"].size(), 3u);
    EXPECT_EQ(repeated[i]["ratio_runs"].size(), 3u);
  }
}

// --solver overrides the scene's solver: naming the scene's own changes
// nothing, the other one changes the run.
TEST(Cli, SolverOptionOverridesTheScenesSolver) {
  const auto hashOf = [](const std::string& arguments) {
    const Result result = run("simulate stack --steps 120 --hash" + arguments);
    EXPECT_EQ(result.exitCode, 0) << arguments << "\n" << result.output;
    return result.output.substr(result.output.find("state hash"));
  };
  const std::string scenes = hashOf("");
  EXPECT_EQ(hashOf(" --solver sequential_impulse"), scenes);
  EXPECT_NE(hashOf(" --solver seed"), scenes);
}

TEST(Cli, BadSceneFilesExitTwoNamingFileAndKey) {
  TempDir dir;
  struct Case {
    const char* json;
    const char* mentions;
  };
  for (const Case& c : {Case{R"({"bodies": [{"shape": {"sphere": {"radius": -1}}}]})", "bodies[0].shape.sphere.radius"},
                        Case{R"({"bodies": [{"shape": {"box": {"half_extents": [1, 1]}}}]})", "half_extents"},
                        Case{R"({"bodies": [], "dt": -1})", "dt"}, Case{R"({"bodies": [})", "malformed JSON"},
                        Case{R"({"bodies": [], "wind": 3})", "wind"},
                        Case{R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "mass": "heavy"}]})", "mass"},
                        Case{R"({"bodies": [{"shape": {"mesh": {"vertices": [[0,0,0],[1,0,0],[0,0,1]],
                             "triangles": [[0,2,3]]}}, "static": true}]})",
                             "bodies[0].shape.mesh.triangles[0][2]"}}) {
    const std::string scene = dir.file("bad.json", c.json);
    for (const std::string& command : {"simulate " + scene, "render " + scene + " -o " + dir.path() + "/frames"}) {
      const Result result = run(command);
      EXPECT_EQ(result.exitCode, 2) << c.json << "\n" << result.output;
      EXPECT_NE(result.output.find("bad.json"), std::string::npos) << result.output;
      EXPECT_NE(result.output.find(c.mentions), std::string::npos) << result.output;
    }
  }
}

TEST(Cli, ScenesListsTheDefaultScene) {
  const Result result = run("scenes");
  EXPECT_EQ(result.exitCode, 0);
  EXPECT_NE(result.output.find("default"), std::string::npos);
}

TEST(Cli, TraceHasTheDocumentedHeaderAndOneRowPerBodyPerStep) {
  TempDir dir;
  const std::string scene = dir.file("two.json", R"({"steps": 5, "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 10, 0]},
      {"shape": {"box": {"half_extents": [1, 1, 1]}}, "static": true}]})");
  const std::string trace = dir.file("trace.csv");
  const Result result = run("simulate " + scene + " --trace " + trace);
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::ifstream file(trace);
  std::string header;
  std::getline(file, header);
  EXPECT_EQ(header, "step,time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz");
  std::vector<std::string> rows;
  for (std::string line; std::getline(file, line);) rows.push_back(line);
  ASSERT_EQ(rows.size(), 2u * 6u);
  EXPECT_EQ(rows[0].rfind("0,0,0,0,10,0,1,0,0,0,", 0), 0u) << rows[0];
  // Step 1 of semi-implicit Euler in 8 substeps of h = dt / 8 (the default):
  // v = 8 g h = g dt, y = 10 + g h^2 (1 + 2 + ... + 8).
  std::istringstream row(rows[2]);
  std::vector<double> values;
  for (std::string cell; std::getline(row, cell, ',');) values.push_back(std::stod(cell));
  EXPECT_EQ(values[0], 1);
  const double h = 1.0 / 480.0;
  EXPECT_NEAR(values[4], 10 - 9.81 * h * h * 36, 1e-12);
  EXPECT_NEAR(values[11], -9.81 / 60.0, 1e-12);
}

// Bodies added or removed during the run: the trace lists a body only in the
// states it is present in (add_at_step <= step < remove_at_step), and the
// events say when the removed body's contact ended.
TEST(Cli, TraceListsOnlyTheBodiesPresent) {
  TempDir dir;
  const std::string scene = dir.file("comings.json", R"({"steps": 6, "gravity": [0, 0, 0], "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [3, 0, 0], "add_at_step": 2},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [0.998, 0, 0], "remove_at_step": 4}]})");
  const std::string trace = dir.file("trace.csv");
  const Result result = run("simulate " + scene + " --trace " + trace + " --events");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  std::ifstream file(trace);
  std::string line;
  std::getline(file, line);
  std::map<int, std::vector<int>> bodiesAt;
  while (std::getline(file, line)) {
    std::istringstream row(line);
    std::string step, time, body;
    std::getline(row, step, ',');
    std::getline(row, time, ',');
    std::getline(row, body, ',');
    bodiesAt[std::stoi(step)].push_back(std::stoi(body));
  }
  ASSERT_EQ(bodiesAt.size(), 7u);
  for (int step = 0; step <= 6; ++step) {
    std::vector<int> expected{0};
    if (step >= 2) expected.push_back(1);
    if (step < 4) expected.push_back(2);
    EXPECT_EQ(bodiesAt[step], expected) << "step " << step;
  }
  EXPECT_NE(result.output.find("step 4 end 0 2"), std::string::npos) << result.output;
}

TEST(Cli, SimulateHashIsTheSameRunAfterRun) {
  const Result first = run("simulate default --steps 60 --hash");
  const Result second = run("simulate default --steps 60 --hash");
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const auto hashOf = [](const std::string& output) { return output.substr(output.find("state hash")); };
  EXPECT_EQ(hashOf(first.output), hashOf(second.output));
}

TEST(Cli, RenderWritesFramesThatShowTheScene) {
  TempDir dir;
  const std::string scene = dir.file("red.json", R"({"steps": 3, "layers": "shapes",
      "camera": {"eye": [0, 0, 8], "target": [0, 0, 0]},
      "bodies": [{"shape": {"box": {"half_extents": [1, 1, 1]}}, "use_gravity": false}]})");
  const Result result = run("render " + scene + " -o " + dir.path() + "/frames --size 64x48");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  for (int frame = 0; frame < 4; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/frames/frame_%05d.png", frame);
    ASSERT_TRUE(fs::exists(dir.path() + name)) << name;
  }
  EXPECT_FALSE(fs::exists(dir.path() + "/frames/frame_00004.png"));
  const physdbg::render::Image image = physdbg::render::readPng(dir.path() + "/frames/frame_00000.png");
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  // The body is lit and coloured (not background, not grey) in the middle, background in a corner.
  const auto at = [&](int x, int y) { return &image.rgba[(static_cast<std::size_t>(y) * 64 + x) * 4]; };
  const std::uint8_t* centre = at(32, 24);
  const std::uint8_t* corner = at(1, 1);
  EXPECT_GT(std::max({centre[0], centre[1], centre[2]}) - std::min({centre[0], centre[1], centre[2]}), 40);
  EXPECT_LT(corner[0] + corner[1] + corner[2], 120);
}

}  // namespace
