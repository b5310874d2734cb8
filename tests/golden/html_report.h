#pragma once
// The report of failed golden comparisons: REPORT/CASE/{expected,actual,diff}.png
// and figures.txt per failed case, and REPORT/index.html showing expected,
// actual and diff side by side. Each test process writes only its own case
// folder and then rebuilds the index from the folders present, so tests run
// in parallel do not lose each other's entries.
#include <filesystem>
#include <string>

#include "render/image.h"

namespace physdbg::golden {

struct FailedComparison {
  std::string caseName;
  std::string figures;  // one line, as printed by physdbg compare
  const render::Image* expected = nullptr;
  const render::Image* actual = nullptr;
  const render::Image* diff = nullptr;
};

// Returns the case folder. Throws std::invalid_argument for missing images,
// std::runtime_error when files cannot be written.
std::filesystem::path recordFailure(const std::filesystem::path& reportRoot, const FailedComparison& failure);

// Removes a case's folder (it passed now) and rebuilds the index.
void clearFailure(const std::filesystem::path& reportRoot, const std::string& caseName);

std::filesystem::path reportIndex(const std::filesystem::path& reportRoot);

}  // namespace physdbg::golden
