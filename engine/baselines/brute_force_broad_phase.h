#pragma once
// O(n^2) broad phase: the reference the tree is tested against and the
// baseline the design compares with. With checkBothOrders it tests A-B and
// B-A like the design's original loop (the pair is still reported once).
// With a task system, rows (each proxy against the later ones) run in
// parallel; the pairs are sorted afterwards, so the result is the same.
#include <vector>

#include "engine/broadphase/broad_phase.h"

namespace physdbg {

class TaskSystem;

struct BruteForceOptions {
  double margin = 0.0;  // fat box = tight box + margin, refreshed on every move
  bool checkBothOrders = false;
  const TaskSystem* tasks = nullptr;  // not owned; null runs the rows in order on the caller's thread
};

class BruteForceBroadPhase final : public BroadPhase {
 public:
  explicit BruteForceBroadPhase(const BruteForceOptions& options = {});

  int addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) override;
  void removeProxy(int proxy) override;
  void moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) override;
  void setProxyActive(int proxy, bool active) override;
  void findPairs(std::vector<BodyPair>& pairs) override;
  const Aabb& fatBox(int proxy) const override;
  BroadPhaseStats stats() const override { return stats_; }

 private:
  struct Slot {
    Aabb box;
    std::uint32_t body = 0;
    ProxyMotion motion = ProxyMotion::Static;
    bool active = true;
    bool alive = false;
  };
  // One proxy's pairs with the proxies it is tested against (findPairs).
  struct Row {
    long long boxesTested = 0;
    std::vector<BodyPair> pairs;
  };
  void findRowPairs(int proxy, Row& row) const;
  void requireProxy(int proxy, const char* operation) const;
  bool drivesPairs(const Slot& slot) const { return slot.motion == ProxyMotion::Dynamic && slot.active; }

  BruteForceOptions options_;
  std::vector<Slot> slots_;
  std::vector<int> freeSlots_;  // reused lowest-last, so ids stay deterministic
  std::vector<Row> rows_;        // per slot, kept so their pair lists keep their capacity
  BroadPhaseStats stats_;
};

}  // namespace physdbg
