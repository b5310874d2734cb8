// The narrow-phase shader's tolerances are written from the CPU's constants
// (narrow_phase_tolerances.h, manifold_points.h, NarrowPhaseOptions), not
// retyped: every `const double` the shader declares reads back as exactly
// the C++ value it stands for. No GL context needed: this checks the text.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <regex>
#include <string>

#include "engine/contacts/manifold_points.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/narrowphase/narrow_phase_tolerances.h"
#include "gpu/narrow_phase_shader.h"

namespace physdbg::gpu {
namespace {

TEST(NarrowPhaseShaderSource, TakesEveryToleranceFromTheCpuConstants) {
  const std::map<std::string, double> cpu = {
      {"kParallelSine", tolerances::parallelSine},
      {"kTieTolerance", tolerances::tieTolerance},
      {"kWitnessTolerance", tolerances::witnessTolerance},
      {"kTouchingTolerance", NarrowPhaseOptions{}.touchingTolerance},
      {"kMinimumFaceAlignment", minimumFaceAlignment},
      {"kReferenceFaceHysteresis", referenceFaceHysteresis},
      {"kClipTolerance", clipTolerance},
      {"kReductionTieMargin", tolerances::reductionTieMargin},
  };
  const std::string source = narrowPhaseShaderSource();
  const std::regex declaration(R"(const double (k\w+) = ([-+0-9.eE]+)lf;)");
  std::map<std::string, int> seen;
  for (auto it = std::sregex_iterator(source.begin(), source.end(), declaration); it != std::sregex_iterator(); ++it) {
    const std::string name = (*it)[1];
    ++seen[name];
    const auto found = cpu.find(name);
    if (found == cpu.end()) continue;  // the shader's own (kDegenerateCore, kHuge)
    EXPECT_EQ(std::strtod(std::string((*it)[2]).c_str(), nullptr), found->second) << name;
  }
  for (const auto& [name, value] : cpu) EXPECT_EQ(seen[name], 1) << name << " declared once";
}

}  // namespace
}  // namespace physdbg::gpu
