// physdbg report solver --quick: one plot per stiff scene, index.html showing
// them, physdbg and (when built) Bullet points in the CSV, and physdbg's
// stack getting no deeper as substeps grow.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bullet_world.h"
#include "render/image.h"
#include "tests/cli/cli_test_support.h"

namespace {

using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

const char* const scenes[] = {"stack10", "pyramid20", "mass_stack_100", "mass_stack_1000"};

std::string readText(const std::string& path) {
  std::ifstream file(path);
  return std::string(std::istreambuf_iterator<char>(file), {});
}

struct Row {
  std::string scene, engine;
  int substeps = 0, iterations = 0;
  double penetration = 0.0;
};

// solver.csv: scene,engine,substeps,iterations,ms_per_step,largest_penetration,drift
std::vector<Row> readRows(const std::string& path) {
  std::vector<Row> rows;
  const auto lines = physdbg::clitesting::readLines(path);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream fields(lines[i]);
    std::vector<std::string> cells;
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    if (cells.size() != 7) continue;
    rows.push_back({cells[0], cells[1], std::stoi(cells[2]), std::stoi(cells[3]), std::stod(cells[5])});
  }
  return rows;
}

// One quick report for the three tests, run by whichever comes first (a
// scratch folder needs a running test for its name).
class SolverReport : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!folder_) {
      folder_ = std::make_unique<ScratchFolder>();
      const auto result = runPhysdbg("report solver --quick -o " + *folder_ / "out");
      exitCode_ = result.exitCode;
      output_ = result.output;
    }
    ASSERT_EQ(exitCode_, 0) << output_;
  }
  static std::string file(const std::string& name) { return *folder_ / ("out/" + name); }

 private:
  static inline std::unique_ptr<ScratchFolder> folder_;
  static inline int exitCode_ = -1;
  static inline std::string output_;
};

TEST_F(SolverReport, WritesOnePlotPerSceneAndAnIndexShowingThem) {
  const std::string index = readText(file("index.html"));
  for (const std::string scene : scenes) {
    const physdbg::render::Image image = physdbg::render::readPng(file(scene + ".png"));
    EXPECT_EQ(image.width, 900) << scene;
    EXPECT_GT(std::filesystem::file_size(file(scene + ".png")), 10000u) << scene << ": a plot, not a blank image";
    EXPECT_NE(index.find("<img src=\"" + scene + ".png\""), std::string::npos) << index;
  }
  EXPECT_NE(index.find("<table>"), std::string::npos) << index;
}

TEST_F(SolverReport, EverySceneHasPhysdbgPointsAndBulletOnePerIterationCount) {
  std::map<std::string, std::map<std::string, int>> counts;
  for (const Row& row : readRows(file("solver.csv"))) ++counts[row.scene][row.engine];
  for (const std::string scene : scenes) {
    EXPECT_EQ(counts[scene]["physdbg"], 6) << scene << ": 3 substep counts x 2 iteration counts";
    EXPECT_EQ(counts[scene]["bullet"], physdbg::bench::BulletWorld::available() ? 3 : 0) << scene;
  }
  if (!physdbg::bench::BulletWorld::available()) {
    EXPECT_NE(readText(file("solver.md")).find("bullet: not built"), std::string::npos);
  }
}

// Substeps are the knob that stiffens a stack (solver_settings.h): more of
// them may not leave the 10-box stack deeper. 5% slack for the last step's
// rounding.
TEST_F(SolverReport, StackPenetrationDoesNotGrowWithSubsteps) {
  std::map<int, double> bySubsteps;
  for (const Row& row : readRows(file("solver.csv"))) {
    if (row.scene == "stack10" && row.engine == "physdbg" && row.iterations == 1) bySubsteps[row.substeps] = row.penetration;
  }
  ASSERT_EQ(bySubsteps.size(), 3u);
  double previous = bySubsteps.begin()->second;
  for (const auto& [substeps, penetration] : bySubsteps) {
    EXPECT_LE(penetration, previous * 1.05) << substeps << " substeps";
    previous = penetration;
  }
  EXPECT_LT(bySubsteps.rbegin()->second, bySubsteps.begin()->second) << "16 substeps shallower than 1";
}

}  // namespace
