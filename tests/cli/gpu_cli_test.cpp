// The compute-shader collision stage through the physdbg command: gpu-info,
// --collision gpu on simulate and contacts, the scene key, and the exit-2
// refusal of a context below OpenGL 4.3 (Mesa plays one when asked).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/visual_test_support.h"

namespace physdbg {
namespace {

using visualtesting::Result;
using visualtesting::runPhysdbg;
using visualtesting::ScratchFolder;

constexpr char oldGl[] = "MESA_GL_VERSION_OVERRIDE=3.3";

TEST(GpuCli, GpuInfoNamesTheRendererAndItsComputeLimits) {
  const Result text = runPhysdbg("gpu-info");
  ASSERT_EQ(text.exitCode, 0) << text.output;
  EXPECT_NE(text.output.find("llvmpipe"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("work groups up to"), std::string::npos) << text.output;
  const Result json = runPhysdbg("gpu-info --json");
  ASSERT_EQ(json.exitCode, 0) << json.output;
  const auto parsed = nlohmann::json::parse(json.output);
  EXPECT_TRUE(parsed["compute"].get<bool>());
  EXPECT_GE(parsed["limits"]["work_group_invocations"].get<int>(), 1024);
}

TEST(GpuCli, AContextBelowGl43ExitsTwoSayingWhatIsMissing) {
  const Result info = runPhysdbg("gpu-info", oldGl);
  EXPECT_EQ(info.exitCode, 2) << info.output;
  EXPECT_NE(info.output.find("needs OpenGL 4.3"), std::string::npos) << info.output;
  const Result simulate = runPhysdbg("simulate stack --steps 2 --collision gpu", oldGl);
  EXPECT_EQ(simulate.exitCode, 2) << simulate.output;
  EXPECT_NE(simulate.output.find("need OpenGL 4.3"), std::string::npos) << simulate.output;
  EXPECT_NE(simulate.output.find("OpenGL 3.3"), std::string::npos) << simulate.output;
  // The CPU path does not need compute at all.
  EXPECT_EQ(runPhysdbg("simulate stack --steps 2 --collision cpu", oldGl).exitCode, 0);
}

TEST(GpuCli, BadCollisionValuesExitTwoNamingTheOption) {
  const Result bad = runPhysdbg("simulate stack --collision fpga");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("--collision"), std::string::npos) << bad.output;
  ScratchFolder folder;
  const std::string path = folder / "bad.json";
  std::ofstream(path) << R"({"collision": {"device": "tpu"}, "bodies": []})";
  const Result key = runPhysdbg("simulate " + path);
  EXPECT_EQ(key.exitCode, 2) << key.output;
  EXPECT_NE(key.output.find("collision.device"), std::string::npos) << key.output;
}

TEST(GpuCli, SimulateOnTheGpuReportsTheDeviceAndKeepsTheStackStanding) {
  const Result run = runPhysdbg("simulate stack --steps 120 --collision gpu");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("collision on the gpu (llvmpipe"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find(" 0 pairs tested there"), std::string::npos) << run.output;
}

TEST(GpuCli, OnTheGpuTheHashIsTheSameForAnyThreadCount) {
  const std::string run = "simulate pyramid --steps 60 --collision gpu --hash --threads ";
  const Result one = runPhysdbg(run + "1"), four = runPhysdbg(run + "4");
  ASSERT_EQ(one.exitCode, 0) << one.output;
  const std::size_t at = one.output.find("state hash ");
  ASSERT_NE(at, std::string::npos) << one.output;
  EXPECT_NE(four.output.find(one.output.substr(at, 27)), std::string::npos) << four.output;
}

// The renderer's context and the collision stage's live side by side, on
// two threads (the frame pipeline steps ahead on its own), through either
// backend; with EGL both come from one display, which neither may close.
TEST(GpuCli, RenderDrawsWhileTheGpuCollidesThroughOsMesaAndEgl) {
  ScratchFolder folder;
  for (const std::string backend : {"osmesa", "egl"}) {
    const Result run = runPhysdbg("render stack --collision gpu --frames 4 --size 160x120 --backend " + backend +
                                  " -o " + folder / backend);
    EXPECT_EQ(run.exitCode, 0) << backend << ": " << run.output;
    EXPECT_TRUE(std::filesystem::exists(folder / (backend + "/frame_00003.png"))) << backend;
  }
}

TEST(GpuCli, TheSceneKeyChoosesTheGpuAndARecordCommandRefusesIt) {
  ScratchFolder folder;
  const std::string path = folder / "gpu.json";
  std::ofstream(path) << R"({"collision": {"device": "gpu"}, "steps": 30, "bodies": [
      {"shape": {"box": {"half_extents": [5, 0.5, 5]}}, "static": true},
      {"shape": {"sphere": {"radius": 0.5}}, "position": [0, 1.2, 0]}]})";
  const Result run = runPhysdbg("simulate " + path);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("collision on the gpu"), std::string::npos) << run.output;
  const Result record = runPhysdbg("record " + path + " -o " + folder / "r.pdbg");
  EXPECT_EQ(record.exitCode, 2) << record.output;
  EXPECT_NE(record.output.find("--collision gpu"), std::string::npos) << record.output;
}

TEST(GpuCli, ContactsOnTheGpuMatchTheCpu) {
  const Result cpu = runPhysdbg("contacts default --json");
  const Result gpu = runPhysdbg("contacts default --json --collision gpu");
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  ASSERT_EQ(gpu.exitCode, 0) << gpu.output;
  const auto a = nlohmann::json::parse(cpu.output), b = nlohmann::json::parse(gpu.output);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i]["a"], b[i]["a"]);
    EXPECT_EQ(a[i]["b"], b[i]["b"]);
    EXPECT_NEAR(a[i]["depth"].get<double>(), b[i]["depth"].get<double>(), 1e-5) << "contact " << i;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(a[i]["normal"][k].get<double>(), b[i]["normal"][k].get<double>(), 1e-5) << "contact " << i;
  }
}

TEST(GpuCli, BenchGpuQuickPrintsBothDevicesAndTheirRatio) {
  const Result run = runPhysdbg("bench gpu --quick --json");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::istringstream lines(run.output);
  int records = 0;
  for (std::string line; std::getline(lines, line);) {
    const auto record = nlohmann::json::parse(line);
    EXPECT_GT(record["ours_ms"].get<double>(), 0.0);
    EXPECT_GT(record["peer_ms"].get<double>(), 0.0);
    EXPECT_GT(record["pairs_on_gpu_per_step"].get<double>(), 0.0);
    EXPECT_TRUE(record.contains("dispatch_ms"));
    ++records;
  }
  EXPECT_EQ(records, 2);  // spheres and boxes
}

}  // namespace
}  // namespace physdbg
