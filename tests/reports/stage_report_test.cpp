#include <gtest/gtest.h>

#include "reports/stage_report.h"

namespace physdbg::reports {
namespace {

// Counters, not claims: spheres never reach GJK/EPA, no layers means no
// primitives, and boxes do reach GJK.
TEST(StageReport, SpheresOnlySceneRunsNoGjkOrEpa) {
  const StageCounters counters = countStages(resolveScene("balls48"), 30, "");
  EXPECT_GT(counters.narrowPairs, 0);
  EXPECT_EQ(counters.gjk, 0);
  EXPECT_EQ(counters.epa, 0);
  EXPECT_EQ(counters.fastPath, counters.narrowPairs);
  EXPECT_EQ(counters.primitivesEmitted, 0);
}

TEST(StageReport, BoxesRunTheBoxBoxPathAndRequestedLayersEmitPrimitives) {
  const StageCounters counters = countStages(resolveScene("stack"), 5, "shapes");
  EXPECT_GT(counters.boxBox, 0);
  EXPECT_GT(counters.primitivesEmitted, 0);
}

TEST(StageReport, UnknownLayerIsRejected) {
  EXPECT_THROW(countStages(resolveScene("stack"), 1, "no_such_layer"), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::reports
