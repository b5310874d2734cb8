// `physdbg simulate --hash` is the same for any --threads (and for the
// scene's "threads" key): the end-to-end half of the cross-thread
// determinism test (tests/engine/thread_determinism_test.cpp compares worlds
// step by step). A bad --threads exits 2 naming the option.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/visual_test_support.h"

namespace physdbg {
namespace {

using visualtesting::Result;
using visualtesting::runPhysdbg;

std::string stateHash(const Result& result) {
  const std::size_t at = result.output.find("state hash ");
  return at == std::string::npos ? "" : result.output.substr(at, result.output.find('\n', at) - at);
}

struct HashCase {
  std::string scene;
  int steps;
};

class ThreadHash : public ::testing::TestWithParam<HashCase> {};

TEST_P(ThreadHash, IsTheSameForOneTwoAndFourThreads) {
  const std::string run = "simulate " + GetParam().scene + " --steps " + std::to_string(GetParam().steps) + " --hash";
  const Result single = runPhysdbg(run + " --threads 1");
  ASSERT_EQ(single.exitCode, 0) << single.output;
  ASSERT_FALSE(stateHash(single).empty()) << single.output;
  for (const std::string threads : {"2", "4", "0"}) {
    const Result many = runPhysdbg(run + " --threads " + threads);
    ASSERT_EQ(many.exitCode, 0) << many.output;
    EXPECT_EQ(stateHash(many), stateHash(single)) << "--threads " << threads;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ThreadHash,
                         ::testing::Values(HashCase{"pyramid", 120}, HashCase{"default", 150},
                                           HashCase{"stack", 300},
                                           HashCase{PHYSDBG_SOURCE_DIR "/scenes/mixed_pile.json", 90},
                                           HashCase{PHYSDBG_SOURCE_DIR "/scenes/arrivals.json", 240}),
                         [](const ::testing::TestParamInfo<HashCase>& info) {
                           std::string name = info.param.scene.substr(info.param.scene.rfind('/') + 1);
                           name = name.substr(0, name.find('.'));
                           return name;
                         });

TEST(ThreadOption, BadValuesExitTwoNamingTheOption) {
  for (const std::string value : {"-1", "x", "257", "1.5", ""}) {
    for (const std::string command : {"simulate stack --steps 1", "contacts stack", "bench pyramid --quick"}) {
      const Result result = runPhysdbg(command + " --threads '" + value + "'");
      EXPECT_EQ(result.exitCode, 2) << command << " --threads '" << value << "': " << result.output;
      EXPECT_NE(result.output.find("--threads"), std::string::npos) << result.output;
    }
  }
}

TEST(ThreadOption, TheCommandLineBeatsTheScene) {
  visualtesting::ScratchFolder folder;
  const std::string scene = folder / "threads.json";
  std::ofstream(scene) << R"({"threads": 2, "bodies": [{"shape": {"sphere": {"radius": 1}}, "position": [0, 3, 0]},
      {"shape": {"box": {"half_extents": [4, 0.5, 4]}}, "static": true}]})";
  const Result fromScene = runPhysdbg("simulate " + scene + " --steps 60 --hash");
  const Result fromOption = runPhysdbg("simulate " + scene + " --steps 60 --hash --threads 1");
  ASSERT_EQ(fromScene.exitCode, 0) << fromScene.output;
  ASSERT_EQ(fromOption.exitCode, 0) << fromOption.output;
  EXPECT_EQ(stateHash(fromScene), stateHash(fromOption));
  EXPECT_NE(fromScene.output.find("on 2 threads"), std::string::npos) << fromScene.output;
  EXPECT_NE(fromOption.output.find("on 1 thread,"), std::string::npos) << fromOption.output;
  const Result bad = runPhysdbg("simulate " + scene + " --steps 1 --threads 300");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
}

}  // namespace
}  // namespace physdbg
