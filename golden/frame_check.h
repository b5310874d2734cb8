#pragma once
// One approved frame against one rendered now, by the project's rule
// (render/image_compare.h, also `physdbg compare`). Both the golden tests and
// `physdbg golden check` judge frames here, so a frame passes or fails the
// same way in either, and a failure leaves the same pictures for the report.
#include <filesystem>
#include <string>

#include "golden/results.h"
#include "render/image.h"

namespace physdbg::golden {

struct FrameToCheck {
  std::string label;  // "frame 10"
  const render::Image* expected = nullptr;
  const render::Image* actual = nullptr;
};

// Compares the images. When they differ and `reportRoot` is not empty, writes
// REPORT/FOLDER/{expected,actual,diff}.png and names FOLDER in the result.
// Throws std::invalid_argument for a missing image, std::runtime_error when
// the pictures cannot be written.
FrameResult checkFrame(const FrameToCheck& frame, const std::filesystem::path& reportRoot, const std::string& folder);

}  // namespace physdbg::golden
