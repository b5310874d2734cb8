#pragma once
// `simulate --series`: one row of whole-world figures per step, so energy
// drift, momentum, contact counts and cost can be plotted over a run
// (`physdbg plot`). The columns are documented in README.md.
#include <string>

#include "cli/csv_output.h"

namespace physdbg {
class World;
}

namespace physdbg::cli {

struct SeriesRow {
  int step = 0;
  double time = 0;
  double kineticEnergy = 0;    // J, dynamic bodies that are not frozen
  double potentialEnergy = 0;  // J, -m g.x over dynamic bodies under gravity (zero at the origin)
  double linearMomentum = 0;   // |sum m v|, kg m/s
  double angularMomentum = 0;  // |sum (x cross m v + I w)| about the world origin, kg m^2/s
  int contacts = 0;            // StepStats::contacts (what simulate prints)
  double maxPenetration = 0;   // StepStats::largestPenetration, m
  int awake = 0;               // StepStats::awakeBodies
  int substeps = 0;            // StepStats::substeps (0 for the seed solver)
  double stepMilliseconds = 0; // wall time of World::step(); 0 for step 0
};

inline constexpr char seriesHeader[] =
    "step,time,kinetic_energy,potential_energy,linear_momentum,angular_momentum,contacts,max_penetration,awake,"
    "substeps,step_ms";

// The world's figures after its last step (step 0: the initial state, whose
// counters are all zero).
SeriesRow measureSeries(const World& world, double stepMilliseconds);

class SeriesWriter {
 public:
  explicit SeriesWriter(const std::string& path) : output_("--series", path, seriesHeader) {}
  // Full precision (%.17g), like --trace.
  void write(const SeriesRow& row);
  void close() { output_.close(); }

 private:
  CsvOutput output_;
};

}  // namespace physdbg::cli
