#include "golden/frame_check.h"

#include <stdexcept>

#include "render/image_compare.h"

namespace physdbg::golden {
namespace {

void writePictures(const FrameToCheck& frame, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  render::writePng((folder / "expected.png").string(), *frame.expected);
  render::writePng((folder / "actual.png").string(), *frame.actual);
  render::writePng((folder / "diff.png").string(), render::diffImage(*frame.expected, *frame.actual));
}

}  // namespace

FrameResult checkFrame(const FrameToCheck& frame, const std::filesystem::path& reportRoot, const std::string& folder) {
  if (!frame.expected || !frame.actual) throw std::invalid_argument("checkFrame: both images are needed");
  const render::CompareResult comparison = render::compareImages(*frame.expected, *frame.actual);
  FrameResult result{frame.label, comparison.passed ? Verdict::Passed : Verdict::Failed,
                     render::describeComparison(comparison), ""};
  if (comparison.passed || reportRoot.empty()) return result;
  writePictures(frame, reportRoot / folder);
  result.images = folder;
  return result;
}

}  // namespace physdbg::golden
