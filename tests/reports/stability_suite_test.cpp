#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "reports/stability_case.h"

namespace physdbg::reports {
namespace {

// The CTest cases name suite entries; a renamed entry must not vanish silently.
TEST(StabilitySuite, NamesAreUniqueAndEveryCaseStatesItsCriterion) {
  std::set<std::string> names;
  for (const StabilityCase& entry : stabilitySuite()) {
    EXPECT_TRUE(names.insert(entry.name).second) << entry.name;
    EXPECT_FALSE(entry.criterion.empty()) << entry.name;
    EXPECT_FALSE(entry.unit.empty()) << entry.name;
  }
  EXPECT_EQ(names.size(), 19u);
}

TEST(StabilitySuite, UnknownCaseIsRejected) {
  EXPECT_THROW(findStabilityCase("no_such_case"), std::invalid_argument);
}

}  // namespace
}  // namespace physdbg::reports
