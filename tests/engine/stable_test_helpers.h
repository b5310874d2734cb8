#pragma once
// Shared by the stable contact acceptance tests (stable_*_test.cpp): build a
// scene's world and print the figure a criterion was judged on, so a log
// shows the margin and not just pass or fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg::stable {

inline void reportFigure(const std::string& what, double value) {
  std::printf("[ measured ] %s = %.6g\n", what.c_str(), value);
  ::testing::Test::RecordProperty(what, std::to_string(value));
}

// Largest penetration the solver left after each of `steps` steps.
inline double stepAndTrackPenetration(World& world, int steps) {
  double deepest = 0.0;
  for (int i = 0; i < steps; ++i) {
    world.step();
    deepest = std::max(deepest, world.lastStepStats().largestPenetration);
  }
  return deepest;
}

}  // namespace physdbg::stable
