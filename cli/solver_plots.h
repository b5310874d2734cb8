#pragma once
// The solver report's work-precision plots: largest penetration and drift
// against ms per step, both axes logarithmic, one plot per scene, each
// engine's two figures as separate series with markers.
#include <filesystem>
#include <string>
#include <vector>

#include "reports/solver_report.h"

namespace physdbg::render {
class Renderer;
}

namespace physdbg::cli {

// Figures below this (a drift of exactly 0) are drawn at it; the title says so.
inline constexpr double smallestPlottedLength = 1e-7;

// Writes `png`; a failed write is a UsageError naming -o.
void writeSolverPlot(render::Renderer& renderer, const std::filesystem::path& png, const std::string& scene,
                     const std::vector<reports::SolverPoint>& points);

}  // namespace physdbg::cli
