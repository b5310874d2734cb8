#include "stability_test_support.h"

namespace physdbg::reports {
namespace {

TEST(StabilityStacking, TallStack) { expectStable("tall_stack"); }
TEST(StabilityStacking, LargePyramid) { expectStable("large_pyramid"); }
TEST(StabilityStacking, MassRatio100) { expectStable("mass_ratio_100"); }
TEST(StabilityStacking, MassRatio1000) { expectStable("mass_ratio_1000"); }
TEST(StabilityStacking, MassRatio10000) { expectStable("mass_ratio_10000"); }
TEST(StabilityStacking, FarPyramid1e4) { expectStable("far_pyramid_1e4"); }
TEST(StabilityStacking, FarPyramid1e6) { expectStable("far_pyramid_1e6"); }
TEST(StabilityStacking, FarPyramid1e7) { expectStable("far_pyramid_1e7"); }
TEST(StabilityStacking, LargeTimeStep) { expectStable("large_dt"); }
TEST(StabilityStacking, SmallTimeStep) { expectStable("small_dt"); }

}  // namespace
}  // namespace physdbg::reports
