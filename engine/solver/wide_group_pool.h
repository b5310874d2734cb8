#pragma once
// Storage for the wide groups of the batches being solved, and their point
// slots. A batch's groups
// live only while it runs (built, swept, impulses stored back), but a
// 4000-box pile's groups together are megabytes: kept per batch, every batch
// wrote its groups into memory the caches had long dropped, and building
// them cost twice as much per box as in a 1000-box pile. Lent last in,
// first out, the storage a thread has just used comes back to it while it
// is still in its caches. Every field a sweep reads is written before it is
// read (WideGroups), so which storage a batch borrows changes no result.
#include <mutex>
#include <utility>
#include <vector>

#include "engine/solver/wide_contact_rows.h"

namespace physdbg {

class WideGroupPool {
 public:
  // Swaps pooled storage into `groups` and `slots` for the loan's lifetime
  // and takes it back at the end; both are left empty.
  class Loan {
   public:
    Loan(WideGroupPool& pool, WideGroups& groups, WideSlots& slots);
    ~Loan();
    Loan(const Loan&) = delete;
    Loan& operator=(const Loan&) = delete;

   private:
    WideGroupPool& pool_;
    WideGroups& groups_;
    WideSlots& slots_;
  };

 private:
  struct Storage {
    WideGroups groups;
    WideSlots slots;
  };
  std::mutex mutex_;
  std::vector<Storage> free_;  // the most recently returned last
};

inline WideGroupPool::Loan::Loan(WideGroupPool& pool, WideGroups& groups, WideSlots& slots)
    : pool_(pool), groups_(groups), slots_(slots) {
  const std::lock_guard lock(pool_.mutex_);
  if (pool_.free_.empty()) return;
  groups_.swap(pool_.free_.back().groups);
  std::swap(slots_, pool_.free_.back().slots);
  pool_.free_.pop_back();
}

inline WideGroupPool::Loan::~Loan() {
  const std::lock_guard lock(pool_.mutex_);
  pool_.free_.emplace_back();
  pool_.free_.back().groups.swap(groups_);
  std::swap(pool_.free_.back().slots, slots_);
}

}  // namespace physdbg
