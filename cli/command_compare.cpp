// physdbg compare: the golden-image comparison as a command. Exit 0 when the
// images match, 1 when they differ, 2 for bad usage or unreadable images.
#include <cstdio>
#include <stdexcept>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/number_option.h"
#include "cli/output_folder.h"
#include "render/image.h"
#include "render/image_compare.h"

namespace physdbg::cli {
namespace {

render::Image readImage(const std::string& path) {
  try {
    return render::readPng(path);
  } catch (const std::runtime_error& error) {
    throw UsageError(error.what());
  }
}

}  // namespace

int runCompare(const std::vector<std::string>& args) {
  const render::CompareOptions defaults;
  const CommandSpec spec{
      "compare",
      "EXPECTED.png ACTUAL.png [--diff FILE.png] [--threshold N] [--max-share F] [--radius R]",
      "Compares two PNGs the way the golden-image tests do: same bytes first; otherwise a pixel differs when a\n"
      "channel differs by more than N levels, unless both images match it within R pixels (thin lines moved by\n"
      "a pixel). The images match when at most a share F of the pixels differ. Exit 0 match, 1 different.",
      {{"--diff", "", "FILE.png", "write a picture of the differences (red: different, yellow: shifted, blue: below "
                                  "the threshold, amplified)"},
       {"--threshold", "", "N", "channel levels 0..255 (default " + std::to_string(defaults.channelThreshold) + ")"},
       {"--max-share", "", "F", "share 0..1 of pixels allowed to differ (default 0.0002)"},
       {"--radius", "", "R", "neighbourhood in pixels, 0..8, 0 = none (default " +
                                 std::to_string(defaults.neighbourhoodRadius) + ")"}},
      2,
      2};
  auto parsed = Arguments::parse(spec, args);
  if (!parsed) return 0;
  render::CompareOptions options;
  options.channelThreshold = numberOption(*parsed, "--threshold", defaults.channelThreshold, 0, 255);
  options.maxDifferentShare = numberOption(*parsed, "--max-share", defaults.maxDifferentShare, 0.0, 1.0);
  options.neighbourhoodRadius = numberOption(*parsed, "--radius", defaults.neighbourhoodRadius, 0, 8);
  const std::string diff = parsed->value("--diff");
  if (parsed->has("--diff")) checkOutputFile(diff, "--diff");
  const render::Image expected = readImage(parsed->positional()[0]);
  const render::Image actual = readImage(parsed->positional()[1]);
  const render::CompareResult result = render::compareImages(expected, actual, options);
  std::printf("%s\n", render::describeComparison(result, options).c_str());
  if (parsed->has("--diff")) {
    writeOutputPng(diff, render::diffImage(expected, actual, options), "--diff");
    std::printf("wrote diff %s\n", diff.c_str());
  }
  return result.passed ? 0 : 1;
}

}  // namespace physdbg::cli
