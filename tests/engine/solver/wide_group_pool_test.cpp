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
  const WideManifolds* used = nullptr;
  {
    const WideGroupPool::Loan loan(pool, first);
    first.resize(40);
    used = first.data();
  }
  EXPECT_TRUE(first.empty());
  {
    const WideGroupPool::Loan loan(pool, second);
    EXPECT_EQ(second.data(), used);  // the same storage, still large enough
    EXPECT_GE(second.capacity(), 40u);
    second.resize(10);
  }
  EXPECT_TRUE(second.empty());
}

TEST(WideGroupPool, LoansHeldAtOnceNeverShareStorage) {
  WideGroupPool pool;
  WideGroups a, b, c;
  {
    const WideGroupPool::Loan one(pool, a), two(pool, b);
    a.resize(8);
    b.resize(8);
  }
  const WideGroupPool::Loan one(pool, a), two(pool, b), three(pool, c);
  a.resize(8);
  b.resize(8);
  c.resize(8);
  EXPECT_NE(a.data(), b.data());
  EXPECT_NE(b.data(), c.data());
  EXPECT_NE(a.data(), c.data());
}

}  // namespace
}  // namespace physdbg
