#include "stability_test_support.h"

namespace physdbg::reports {
namespace {

TEST(StabilityShapes, TinyBodies) { expectStable("tiny_bodies"); }
TEST(StabilityShapes, HugeBodies) { expectStable("huge_bodies"); }
TEST(StabilityShapes, ThinPlate) { expectStable("thin_plate"); }
TEST(StabilityShapes, DegenerateMesh) { expectStable("degenerate_mesh"); }

}  // namespace
}  // namespace physdbg::reports
