#pragma once
// The accuracy report's work-precision plots (error against run time, both
// logarithmic, one curve per method), drawn by the one plotter in viewer/.
#include <filesystem>
#include <string>

#include "reports/accuracy_report.h"

namespace physdbg::render {
class Renderer;
}

namespace physdbg::cli {

// Errors are clamped to this so exact methods still show on the log axis; the
// title says so.
inline constexpr double smallestPlottedError = 1e-16;

// Writes `png`; a failed write is a UsageError naming -o.
void writeAccuracyPlot(render::Renderer& renderer, const std::filesystem::path& png, const std::string& reference,
                       const reports::AccuracyMethods& methods);

}  // namespace physdbg::cli
