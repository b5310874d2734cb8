// simulate --series: the columns mean what README.md says, checked against
// free fall (where semi-implicit Euler has a closed form) and a resting stack.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "engine/solver/solver_settings.h"
#include "tests/cli/cli_test_support.h"

namespace {

using physdbg::clitesting::readLines;
using physdbg::clitesting::writeFile;
using physdbg::visualtesting::runPhysdbg;
using physdbg::visualtesting::ScratchFolder;

constexpr char header[] =
    "step,time,kinetic_energy,potential_energy,linear_momentum,angular_momentum,contacts,max_penetration,awake,"
    "substeps,step_ms";

struct SeriesRow {
  double step, time, kinetic, potential, momentum, angular, contacts, penetration, awake, substeps, milliseconds;
};

std::vector<SeriesRow> readSeries(const std::string& path) {
  const std::vector<std::string> lines = readLines(path);
  EXPECT_FALSE(lines.empty());
  if (lines.empty()) return {};
  EXPECT_EQ(lines.front(), header);
  std::vector<SeriesRow> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::stringstream stream(lines[i]);
    SeriesRow row{};
    char comma = 0;
    stream >> row.step >> comma >> row.time >> comma >> row.kinetic >> comma >> row.potential >> comma >>
        row.momentum >> comma >> row.angular >> comma >> row.contacts >> comma >> row.penetration >> comma >>
        row.awake >> comma >> row.substeps >> comma >> row.milliseconds;
    EXPECT_TRUE(stream) << lines[i];
    rows.push_back(row);
  }
  return rows;
}

// One 2 kg sphere at y = 10, nothing to hit, 4 substeps of h = dt / 4.
//
// Semi-implicit Euler with substep h under constant g: v_k = -g k h, which is
// the exact velocity (v' = -g is integrated exactly), and y_k = y0 - h^2 g
// k (k + 1) / 2 = y0 - g t^2 / 2 - g h t / 2 at t = k h: the position lags the
// exact one by g h t / 2. So, at step n (k = 4n substeps):
//   kinetic energy   = m g^2 t^2 / 2 exactly, up to rounding;
//   potential energy = m g y_k (relative to y = 0) = m g (y0 - g t^2/2 - g h t/2);
// and their sum loses m g^2 h t / 2, the method's own energy error.
// Rounding: v is a sum of k terms g h, each addition off by at most one ulp
// of the sum, so |dv| <= k eps |v| and |dKE| <= 2 k eps KE (+ eps for t).
// y accumulates k terms v h the same way: |dy| <= 2 k eps (|y0| + |y - y0|).
TEST(StepSeries, FreeFallFollowsSemiImplicitEulerToRounding) {
  ScratchFolder folder;
  writeFile(folder / "fall.json",
            R"({"name": "fall", "dt": 0.016666666666666666, "steps": 60, "gravity": [0, -9.81, 0],
                "solver": {"substeps": 4},
                "bodies": [{"shape": {"sphere": {"radius": 0.5}}, "position": [0, 10, 0], "mass": 2}]})");
  ASSERT_EQ(runPhysdbg("simulate " + folder / "fall.json" + " --series " + folder / "s.csv").exitCode, 0);
  const std::vector<SeriesRow> rows = readSeries(folder / "s.csv");
  ASSERT_EQ(rows.size(), 61u);
  const double m = 2, g = 9.81, y0 = 10, dt = 1.0 / 60, h = dt / 4, eps = std::numeric_limits<double>::epsilon();
  for (const SeriesRow& row : rows) {
    const double t = row.step * dt, substeps = 4 * row.step;
    const double kinetic = 0.5 * m * g * g * t * t;
    EXPECT_NEAR(row.kinetic, kinetic, (2 * substeps + 4) * eps * kinetic) << "step " << row.step;
    const double y = y0 - 0.5 * g * t * t - 0.5 * g * h * t;
    EXPECT_NEAR(row.potential, m * g * y, m * g * (2 * substeps + 4) * eps * (y0 + std::abs(y - y0)))
        << "step " << row.step;
    EXPECT_NEAR(row.momentum, m * g * t, (substeps + 2) * eps * m * g * t);
    EXPECT_EQ(row.contacts, 0);
  }
  // The energy the method loses, visible in the columns: m g^2 h t / 2.
  const SeriesRow& last = rows.back();
  EXPECT_NEAR(rows.front().potential - (last.kinetic + last.potential), 0.5 * m * g * g * h * last.time, 1e-9);
}

// Ten unit boxes of 1 kg stacked from y = 0.5 on a floor: settling moves
// them by millimetres (each contact settles near 2.5 mm), so the potential
// energy stays within 10 boxes x 9.81 N x 10 cm of the start, motion dies
// down, the last steps take the calm substeps (the stack has been at rest a
// quarter second), and `contacts` is the count simulate prints for the last
// step.
TEST(StepSeries, RestingStackIsSaneAndCountsContactsAsSimulateDoes) {
  ScratchFolder folder;
  const auto result = runPhysdbg("simulate stack --steps 20 --series " + folder / "s.csv");
  ASSERT_EQ(result.exitCode, 0) << result.output;
  const std::vector<SeriesRow> rows = readSeries(folder / "s.csv");
  ASSERT_EQ(rows.size(), 21u);
  const SeriesRow& first = rows.front();
  const SeriesRow& last = rows.back();
  EXPECT_EQ(first.kinetic, 0);
  EXPECT_EQ(first.contacts, 0);  // step 0: no step ran yet
  EXPECT_NEAR(last.potential, first.potential, 10 * 9.81 * 0.1);
  EXPECT_LT(last.kinetic, 0.05);
  EXPECT_LT(last.momentum, 0.5);
  EXPECT_GE(last.penetration, 0);
  EXPECT_LT(last.penetration, 0.01);
  EXPECT_EQ(last.substeps, physdbg::SolverSettings{}.calmSubsteps);
  EXPECT_NE(result.output.find(", " + std::to_string(static_cast<int>(last.contacts)) + " contacts,"),
            std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("last step: " + std::to_string(static_cast<int>(last.awake)) + " awake"),
            std::string::npos)
      << result.output;
}

}  // namespace
