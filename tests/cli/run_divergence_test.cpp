// physdbg diff and simulate --hash-every: two runs that part at a known
// step, body and field are found there; identical runs agree; traces from
// other people that cannot be read exit 2 naming file, line and column.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "render/image.h"
#include "tests/cli/cli_test_support.h"

namespace {

using physdbg::clitesting::readLines;
using physdbg::clitesting::writeFile;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

// Three spheres falling apart (no contacts), 10 steps. `forces` is the
// scene's forces list: the perturbed run nudges body 2 in one step only.
std::string fallingSpheres(const std::string& forces) {
  return R"({"name": "three_spheres", "dt": 0.016666666666666666, "steps": 10, "allow_sleep": false,
    "bodies": [
      {"shape": {"sphere": {"radius": 0.5}}, "position": [-3, 5, 0]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 5, 0]},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [3, 5, 0]}],
    "forces": [)" +
         forces + "]}";
}

// A velocity change of 1e-9 m/s in x on body 2, applied in step 5 (the
// sixth), so the traces agree up to step 5 and part at step 6.
const std::string nudge = R"({"body": 2, "force": [1e-9, 0, 0], "mode": "velocity_change", "steps": [5, 6]})";

class RunDivergence : public ::testing::Test {
 protected:
  ScratchFolder folder;
  std::string same = folder / "same.json", nudged = folder / "nudged.json";
  std::string traceA = folder / "a.csv", traceB = folder / "b.csv";

  void SetUp() override {
    writeFile(same, fallingSpheres(""));
    writeFile(nudged, fallingSpheres(nudge));
    ASSERT_EQ(runPhysdbg("simulate " + same + " --trace " + traceA).exitCode, 0);
    ASSERT_EQ(runPhysdbg("simulate " + nudged + " --trace " + traceB).exitCode, 0);
  }

  // traceA with the line `index` (0 = header) replaced.
  std::string edited(std::size_t index, const std::string& replacement, const std::string& name) {
    std::vector<std::string> lines = readLines(traceA);
    lines.at(index) = replacement;
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    writeFile(folder / name, text);
    return folder / name;
  }
};

// x integrates the nudged velocity in the same step (semi-implicit Euler),
// and comes before vx in the trace; x moved by 1e-9 dt ~ 1.7e-11 m, so a
// tolerance of 1e-10 skips it and finds vx.
TEST_F(RunDivergence, FindsTheNudgedBodyAtItsStep) {
  const auto exact = runPhysdbg("diff " + traceA + " " + traceB);
  EXPECT_EQ(exact.exitCode, 1) << exact.output;
  EXPECT_NE(exact.output.find("traces differ at step 6 body 2, field x\n"), std::string::npos) << exact.output;
  const auto tolerant = runPhysdbg("diff " + traceA + " " + traceB + " --tolerance 1e-10");
  EXPECT_EQ(tolerant.exitCode, 1);
  EXPECT_NE(tolerant.output.find("traces differ at step 6 body 2, field vx\n"), std::string::npos) << tolerant.output;
  EXPECT_EQ(runPhysdbg("diff " + traceA + " " + traceB + " --tolerance 1e-8").exitCode, 0);
}

TEST_F(RunDivergence, IdenticalRunsAgree) {
  const std::string again = folder / "again.csv";
  ASSERT_EQ(runPhysdbg("simulate " + same + " --trace " + again).exitCode, 0);
  const auto result = runPhysdbg("diff " + traceA + " " + again);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("traces agree: 33 rows"), std::string::npos) << result.output;
}

// Line 1 + 3 * 4 + 2 is step 4 body 1 (three bodies a step, step 0 first).
TEST_F(RunDivergence, NamesAnEditedValueAndAMissingRow) {
  const std::string row = readLines(traceA).at(14);
  ASSERT_EQ(row.rfind("4,", 0), 0u) << row;
  const std::string changed = row.substr(0, row.rfind(',')) + ",123";  // wz
  const auto value = runPhysdbg("diff " + traceA + " " + edited(14, changed, "value.csv"));
  EXPECT_EQ(value.exitCode, 1);
  EXPECT_NE(value.output.find("traces differ at step 4 body 1, field wz"), std::string::npos) << value.output;

  std::vector<std::string> lines = readLines(traceA);
  lines.erase(lines.begin() + 14);
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  writeFile(folder / "missing.csv", text);
  const auto missing = runPhysdbg("diff " + traceA + " " + folder / "missing.csv");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("step 4 body 1 is in " + traceA + " (line 15) but not in"), std::string::npos)
      << missing.output;

  lines = readLines(traceA);
  lines.pop_back();
  text.clear();
  for (const std::string& line : lines) text += line + "\n";
  writeFile(folder / "short.csv", text);
  const auto shorter = runPhysdbg("diff " + folder / "short.csv" + " " + traceA);
  EXPECT_EQ(shorter.exitCode, 1);
  EXPECT_NE(shorter.output.find("short.csv ends before step 10 body 2, which " + traceA + " has (line 34)"),
            std::string::npos)
      << shorter.output;
}

// A column only one trace has is a difference; the shared ones still agree.
TEST_F(RunDivergence, NamesAColumnOnlyOneTraceHas) {
  std::string text;
  for (const std::string& line : readLines(traceA)) text += line.substr(0, line.rfind(',')) + "\n";
  writeFile(folder / "narrow.csv", text);
  const auto result = runPhysdbg("diff " + traceA + " " + folder / "narrow.csv" + " --scene-a " + same + " -o " +
                                 folder / "never.png");
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("column 'wz' is only in " + traceA), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("the 13 columns both have agree in all 33 rows"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("nothing to draw"), std::string::npos) << result.output;
}

TEST_F(RunDivergence, BadTracesExitTwoNamingFileLineAndColumn) {
  const std::string row = readLines(traceA).at(5);
  const std::string tail = row.substr(row.find(',') + 1);
  const std::pair<std::string, std::string> cases[] = {
      {edited(5, row.substr(0, row.rfind(',')) + ",nan", "nan.csv"), "nan.csv:6: column 16 ('wz'): 'nan' is not finite"},
      {edited(5, row.substr(0, row.rfind(',')) + ",1.5x", "text.csv"), "text.csv:6: column 16 ('wz'): '1.5x' is not a number"},
      {edited(5, row + ",1", "wide.csv"), "wide.csv:6: more fields than the header's 16 columns"},
      {edited(5, row + std::string(5000, '1'), "long.csv"), "long.csv:6: line longer than 4096 characters"},
      {edited(5, "0," + tail, "order.csv"), "order.csv:6: step 0 body 1 comes after step 1 body 0"},
      {edited(0, "step,time,x", "header.csv"), "header.csv:1: a trace (simulate --trace) has 'step' and 'body'"},
      {edited(0, std::string(70, ','), "columns.csv"), "columns.csv:1: more than 64 columns"},
      {folder / "absent.csv", "cannot read '" + folder / "absent.csv" + "'"}};
  for (const auto& [file, message] : cases) {
    const auto result = runPhysdbg("diff " + traceA + " " + file);
    EXPECT_EQ(result.exitCode, 2) << file << ": " << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << result.output;
  }
}

// Both runs drawn side by side at the step they part, each 160x120.
TEST_F(RunDivergence, DrawsBothRunsAtTheFirstDifferingStep) {
  const std::string picture = folder / "diff.png";
  const auto result = runPhysdbg("diff " + traceA + " " + traceB + " --scene-a " + same + " --scene-b " + nudged +
                                 " --size 160x120 -o " + picture);
  EXPECT_EQ(result.exitCode, 1) << result.output;
  EXPECT_NE(result.output.find("wrote " + picture + ": step 6 of A (left) and B (right)"), std::string::npos)
      << result.output;
  const physdbg::render::Image image = physdbg::render::readPng(picture);
  EXPECT_EQ(image.width, 320);
  EXPECT_EQ(image.height, 120);
  EXPECT_EQ(runPhysdbg("diff " + traceA + " " + traceB + " --scene-b " + nudged).exitCode, 2);
}

TEST(StateHash, LastLineOfHashEveryEqualsHash) {
  const auto result = runPhysdbg("simulate stack --steps 25 --hash-every 10 --hash");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::size_t at = result.output.find("step 25 hash ");
  ASSERT_NE(at, std::string::npos) << result.output;
  EXPECT_NE(result.output.find("step 10 hash "), std::string::npos);
  EXPECT_NE(result.output.find("step 20 hash "), std::string::npos);
  const std::string hash = result.output.substr(at + 13, 16);
  EXPECT_NE(result.output.find("state hash " + hash + "\n"), std::string::npos) << result.output;
}

}  // namespace
