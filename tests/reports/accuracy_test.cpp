#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "reports/accuracy_references.h"
#include "reports/accuracy_report.h"

namespace physdbg::reports {
namespace {

TEST(AccuracyReport, FittedOrderRecoversAPowerLaw) {
  std::vector<AccuracySample> samples;
  for (const double dt : {1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240}) samples.push_back({"r", "m", dt, 3.0 * dt * dt, 1.0, ""});
  EXPECT_NEAR(fittedOrder(samples), 2.0, 1e-12);
}

TEST(AccuracyReport, FittedOrderIgnoresRoundingLevelErrors) {
  std::vector<AccuracySample> samples = {{"r", "m", 0.1, 1e-13, 1.0, ""}, {"r", "m", 0.01, 1e-15, 1.0, ""}};
  EXPECT_TRUE(std::isnan(fittedOrder(samples)));
}

std::vector<AccuracySample> sweep(const std::vector<double>& errors) {
  std::vector<AccuracySample> samples;
  double dt = 1.0 / 30;
  for (const double error : errors) {
    samples.push_back({"r", "m", dt, error, 1.0, ""});
    dt /= 2;
  }
  return samples;
}

// The summary's order column: a number only where it means one.
TEST(AccuracyReport, OrderSaysExactNotMonotoneOrFlatInsteadOfANumber) {
  EXPECT_EQ(fitOrder(sweep({4e-2, 1e-2, 2.5e-3, 6.25e-4})).text, "2.00");
  EXPECT_EQ(fitOrder(sweep({3e-14, 1e-13, 2e-12, 1e-15})).text.rfind("exact (error at round-off", 0), 0u);
  const OrderFit rising = fitOrder(sweep({1e-2, 5e-3, 8e-3, 1e-3}));
  EXPECT_TRUE(std::isnan(rising.order));
  EXPECT_EQ(rising.text, "none: not monotone, error rises from 0.005 at dt 1/60 to 0.008 at dt 1/120");
  EXPECT_EQ(fitOrder(sweep({4.369, 4.369, 4.369, 4.369})).text.rfind("none: error does not fall with dt", 0), 0u);
  EXPECT_EQ(fitOrder(sweep({1e-3, 1e-12, 1e-13, 1e-14})).text,
            "none: only dt 1/30 has an error above round-off (0.001)");
}

const TimeStepReference& reference(const std::string& name) {
  static const auto references = timeStepReferences();
  for (const auto& entry : references) {
    if (entry.name == name) return entry;
  }
  throw std::invalid_argument(name);
}

// Semi-implicit Euler falls g dt^2 n (n + 1) / 2 in n steps: the error at
// T = n dt is exactly g dt T / 2, and the 4 substeps quarter it.
TEST(AccuracyReferences, FreeFallErrorIsTheSemiImplicitEulerTerm) {
  WorldSettings settings;
  settings.dt = 1.0 / 60.0;
  settings.solver.kind = SolverKind::Seed;
  EXPECT_NEAR(reference("free_fall").run(settings).error, 9.81 * settings.dt / 2.0, 1e-9);
  settings.solver.kind = SolverKind::SequentialImpulse;
  settings.solver.substeps = 4;
  EXPECT_NEAR(reference("free_fall").run(settings).error, 9.81 * settings.dt / 8.0, 1e-9);
}

// First order in dt: halving dt halves the error within 10%.
TEST(AccuracyReferences, DragAndSlidingConvergeAtFirstOrder) {
  for (const char* name : {"projectile_drag", "slide_to_rest"}) {
    WorldSettings coarse, fine;
    coarse.dt = 1.0 / 120.0;
    fine.dt = 1.0 / 240.0;
    const double ratio = reference(name).run(coarse).error / reference(name).run(fine).error;
    EXPECT_NEAR(ratio, 2.0, 0.2) << name;
  }
}

TEST(AccuracyReferences, ContactDepthsAreExactForSpheresAndBoxes) {
  for (const DepthReference& entry : depthReferences()) {
    EXPECT_LT(entry.run(NarrowPhaseOptions{}).error, 1e-9) << entry.name;
  }
}

}  // namespace
}  // namespace physdbg::reports
