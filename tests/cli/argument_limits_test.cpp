// Limits on the numbers a command line may ask for (cli/limits.h): beyond
// them a usage error naming the argument (exit 2) before any work; at them
// the command runs. Checked without integer overflow.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/visual_test_support.h"
#include "cli/arguments.h"
#include "cli/limits.h"
#include "cli/view_options.h"

namespace {

namespace limits = physdbg::cli::limits;
using physdbg::cli::parseFrameRange;
using physdbg::cli::parseSize;
using physdbg::cli::UsageError;
using physdbg::visualtesting::Result;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

TEST(ArgumentLimits, ImageSizes) {
  EXPECT_EQ(parseSize("16384x16", "--size"), std::make_pair(16384, 16));
  EXPECT_EQ(parseSize("8192x8192", "--size"), std::make_pair(8192, 8192));
  for (const char* text : {"16385x16", "16x16385", "16384x16384", "8193x8192", "15x16", "4294967312x16",
                           "99999999999999999999x16", "-16x16", "16x16x16"})
    EXPECT_THROW(parseSize(text, "--size"), UsageError) << text;
}

TEST(ArgumentLimits, FrameRanges) {
  EXPECT_EQ(parseFrameRange("0:1000000", "--frames").last, limits::maxFrames);
  EXPECT_EQ(parseFrameRange("1000000", "--frames").count(), limits::maxFrames);
  for (const char* text : {"0:1000001", "0:2147483647", "0:2147483648", "0:99999999999999999999", "1000001", "+3", " 3",
                           "3:", ":3", "5:5", "-1:3"})
    EXPECT_THROW(parseFrameRange(text, "--frames"), UsageError) << text;
}

TEST(ArgumentLimits, PositiveIntegersHaveAMaximum) {
  const physdbg::cli::CommandSpec spec{"test", "", "", {{"--steps", "", "N", ""}}, 0, 0};
  const auto parse = [&](const std::string& value) {
    return physdbg::cli::Arguments::parse(spec, {"--steps", value})->positiveInt("--steps", 1, 100);
  };
  EXPECT_EQ(parse("100"), 100);
  for (const char* text : {"101", "0", "-1", "2147483648", "1e3", "12abc"})
    EXPECT_THROW(parse(text), UsageError) << text;
}

TEST(ArgumentLimits, CommandsRefuseWhatIsOverALimitNamingTheArgument) {
  ScratchFolder folder;
  const std::string longScene = folder / "long.json";
  std::ofstream(longScene) << R"({"steps": 2000000, "bodies": [{"shape": {"sphere": {"radius": 1}}}]})";
  struct Case {
    std::string arguments;
    const char* mentions;
  };
  for (const Case& c :
       {Case{"render default --frames 0:2147483647", "--frames"}, Case{"render default --frames 0:1000001", "--frames"},
        Case{"render default --frames 0:1000000 --steps-per-frame 101", "--steps-per-frame"},
        Case{"record default --steps-per-frame 2147483647 -o x.rec", "--steps-per-frame"},
        Case{"render default --size 16384x16384", "--size"}, Case{"simulate default --steps 100000001", "--steps"},
        Case{"simulate default --steps 4294967297", "--steps"}, Case{"tree default --max-events 10001", "--max-events"},
        Case{"tree default --steps 100000001", "--steps"}, Case{"tree default --size 8193x300", "--size"},
        Case{"replay x.rec -o x --frames 0:1000001", "--frames"}, Case{"render " + longScene, "--frames"}}) {
    const Result result = runPhysdbg(c.arguments);
    EXPECT_EQ(result.exitCode, 2) << c.arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(c.mentions), std::string::npos) << c.arguments << "\n" << result.output;
  }
}

// The largest frame index runs (a million steps of one body: a few seconds at most).
TEST(ArgumentLimits, TheLastAllowedFrameRuns) {
  ScratchFolder folder;
  const std::string scene = folder / "one.json";
  std::ofstream(scene) << R"({"gravity": [0, 0, 0], "bodies": [{"shape": {"sphere": {"radius": 1}}}]})";
  const Result result =
      runPhysdbg("record " + scene + " --frames 999999:1000000 --layers shapes -o " + (folder / "last.rec"));
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("999999..999999"), std::string::npos) << result.output;
}

}  // namespace
