// WideGroupPool lends storage so a batch's groups land where the thread's
// last batch left them: the storage returned last is lent first, loans held
// at once never share storage, and a loan leaves its vector empty.
#include "engine/solver/wide_group_pool.h"

#include <gtest/gtest.h>

namespace physdbg {
namespace {

TEST(WideGroupPool, TheStorageReturnedLastIsLentFirst) {
  WideGroupPool pool;
  WideGroups first, second;
  WideSlots firstSlots, secondSlots;
  const WideManifolds* used = nullptr;
  {
    const WideGroupPool::Loan loan(pool, first, firstSlots);
    first.resize(40);
    used = first.data();
  }
  EXPECT_TRUE(first.empty());
  {
    const WideGroupPool::Loan loan(pool, second, secondSlots);
    EXPECT_EQ(second.data(), used);  // the same storage, still large enough
    EXPECT_GE(second.capacity(), 40u);
    second.resize(10);
  }
  EXPECT_TRUE(second.empty());
}

TEST(WideGroupPool, LoansHeldAtOnceNeverShareStorage) {
  WideGroupPool pool;
  WideGroups a, b, c;
  WideSlots slotsA, slotsB, slotsC;
  {
    const WideGroupPool::Loan one(pool, a, slotsA), two(pool, b, slotsB);
    a.resize(8);
    b.resize(8);
  }
  const WideGroupPool::Loan one(pool, a, slotsA), two(pool, b, slotsB), three(pool, c, slotsC);
  a.resize(8);
  b.resize(8);
  c.resize(8);
  EXPECT_NE(a.data(), b.data());
  EXPECT_NE(b.data(), c.data());
  EXPECT_NE(a.data(), c.data());
}

}  // namespace
}  // namespace physdbg
