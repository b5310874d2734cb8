#include "stability_test_support.h"

namespace physdbg::reports {
namespace {

TEST(StabilityImpacts, OverlapRecovery) { expectStable("overlap_recovery"); }
TEST(StabilityImpacts, BulletIntoThinWall) { expectStable("bullet_200_thin_wall"); }
TEST(StabilityImpacts, BulletIntoStack) { expectStable("bullet_500_stack"); }
TEST(StabilityImpacts, ElasticBounceNeverHigherThanDrop) { expectStable("elastic_bounce"); }
TEST(StabilityImpacts, FastSpinGainsNoEnergy) { expectStable("fast_spin"); }

}  // namespace
}  // namespace physdbg::reports
