// The options several commands share (cli/common_options.h) are declared and
// parsed once: the same text gives the same value, and the same bad text the
// same usage error naming the option, whichever command it is given to.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/support/visual_test_support.h"
#include "cli/common_options.h"

namespace {

using namespace physdbg::cli;
using namespace physdbg::visualtesting;

// The groups as `render` and `replay` take them.
const std::initializer_list<OptionGroup> renderGroups = {OptionGroup::SceneFrames, OptionGroup::ImageSize,
                                                         OptionGroup::SceneLayers, OptionGroup::Focus,
                                                         OptionGroup::Camera,      OptionGroup::Backend};
const std::initializer_list<OptionGroup> replayGroups = {OptionGroup::RecordedFrames, OptionGroup::ImageSize,
                                                         OptionGroup::RecordedLayers, OptionGroup::Focus,
                                                         OptionGroup::Camera,         OptionGroup::Backend};

Arguments parse(const std::string& command, std::initializer_list<OptionGroup> groups,
                const std::vector<std::string>& args) {
  CommandSpec spec{command, "", "", {}, 0, 0};
  addOptions(spec, groups);
  return *Arguments::parse(spec, args);
}

// What follows "physdbg COMMAND: " in a failed run's output.
std::string messageOf(const Result& result) {
  const std::size_t colon = result.output.find(": ");
  return colon == std::string::npos ? result.output : result.output.substr(colon + 2);
}

// The help line of `option` in `command --help`, from the option on.
std::string helpLine(const std::string& command, const std::string& option) {
  const std::string help = runPhysdbg(command + " --help").output;
  const std::size_t start = help.find("  " + option + " ");
  if (start == std::string::npos) return "";
  return help.substr(start, help.find('\n', start) - start);
}

TEST(CommonOptions, ASharedOptionParsesIdenticallyInTwoCommands) {
  const std::vector<std::string> args = {"--size",    "640x360", "--frames=2:5", "--eye", "1,2,3",
                                         "--backend", "egl",     "--samples",    "4"};
  const Arguments render = parse("render", renderGroups, args);
  const Arguments replay = parse("replay", replayGroups, args);
  EXPECT_EQ(readSize(render, defaultImageSize), std::make_pair(640, 360));
  EXPECT_EQ(readSize(replay, defaultImageSize), readSize(render, defaultImageSize));
  const FrameRange renderFrames = *readFrames(render), replayFrames = *readFrames(replay);
  EXPECT_EQ(renderFrames.first, 2);
  EXPECT_EQ(renderFrames.last, 5);
  EXPECT_TRUE(renderFrames.slice);
  EXPECT_EQ(replayFrames.first, renderFrames.first);
  EXPECT_EQ(replayFrames.last, renderFrames.last);
  EXPECT_EQ(replayFrames.slice, renderFrames.slice);
  EXPECT_EQ(*readCameraOptions(render).eye, physdbg::debugdraw::Vec3(1, 2, 3));
  EXPECT_EQ(*readCameraOptions(replay).eye, *readCameraOptions(render).eye);
  EXPECT_EQ(readBackend(render), physdbg::render::Backend::Egl);
  EXPECT_EQ(readBackend(replay), readBackend(render));
  EXPECT_EQ(readSamples(render), 4);
  EXPECT_EQ(readSamples(replay), readSamples(render));
}

TEST(CommonOptions, ABadValueIsAUsageErrorNamingTheOptionAndTheValue) {
  for (const auto& groups : {renderGroups, replayGroups}) {
    const Arguments arguments = parse("render", groups, {"--size", "12", "--backend", "vulkan"});
    try {
      readSize(arguments, defaultImageSize);
      ADD_FAILURE() << "--size 12 was accepted";
    } catch (const UsageError& error) {
      EXPECT_NE(std::string(error.what()).find("--size"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("'12'"), std::string::npos) << error.what();
    }
    EXPECT_THROW(readBackend(arguments), UsageError);
  }
}

// Through the commands themselves: exit code 2 and the same message.
TEST(CommonOptions, CommandsRefuseABadSharedValueWithTheSameMessage) {
  ScratchFolder folder;
  const Result render = runPhysdbg("render default --size 12 -o " + (folder / "frames"));
  const Result replay = runPhysdbg("replay " + (folder / "none.rec") + " -o " + (folder / "frames") + " --size 12");
  const Result record = runPhysdbg("record default -o " + (folder / "x.rec") + " --size 12");
  for (const Result& result : {render, replay, record}) {
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("--size"), std::string::npos) << result.output;
  }
  EXPECT_EQ(messageOf(replay), messageOf(render));
  EXPECT_EQ(messageOf(record), messageOf(render));
}

TEST(CommonOptions, HelpDescribesASharedOptionTheSameWayInEveryCommand) {
  const std::string backend = helpLine("render", "--backend");
  EXPECT_NE(backend.find("osmesa|egl"), std::string::npos) << backend;
  EXPECT_EQ(helpLine("replay", "--backend"), backend);
  EXPECT_EQ(helpLine("tree", "--backend"), backend);
  const std::string eye = helpLine("render", "--eye");
  EXPECT_FALSE(eye.empty());
  EXPECT_EQ(helpLine("record", "--eye"), eye);
  EXPECT_EQ(helpLine("replay", "--eye"), eye);
}

}  // namespace
