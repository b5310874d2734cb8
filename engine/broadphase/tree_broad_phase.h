#pragma once
// Broad phase over a DynamicAabbTree with incremental pair finding: only
// proxies whose fat box changed (reinserted, added, woken, put to sleep) query
// the tree; pairs between proxies that did not change are carried over from
// the previous call, since neither their boxes nor their eligibility changed.
// With a task system the queries run in parallel, in fixed pieces of the
// changed list; their pairs are sorted before they are merged, so the pairs
// and the tree are the same for any thread count.
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/broadphase/broad_phase.h"
#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg {

class TaskSystem;

class TreeBroadPhase final : public BroadPhase {
 public:
  // Fewer changed proxies (moved out of their fat boxes, added, removed, put
  // to sleep or woken) than this query on the caller's thread. The other
  // thread's reads pull tree nodes into its cache, and the next step's edits
  // must pull them back: on the 2-vCPU machines here (about 400 ns a cache
  // line's round trip) that cost more than the split saved below about 4000
  // queries (bench tree "moving": 8192 proxies, 1090 queries a step, 5%
  // slower on 2 threads; 32768 proxies, 4360 queries, 7-9% faster).
  static constexpr int parallelQueryMinimum = 4096;

  // tasks: not owned, must outlive the broad phase; null queries on the caller's thread.
  explicit TreeBroadPhase(const DynamicAabbTreeOptions& options = {}, const TaskSystem* tasks = nullptr);

  int addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) override;
  void removeProxy(int proxy) override;
  void moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) override;
  void setProxyActive(int proxy, bool active) override;
  void findPairs(std::vector<BodyPair>& pairs) override;
  const Aabb& fatBox(int proxy) const override { return tree_.fatBox(proxy); }
  BroadPhaseStats stats() const override { return stats_; }

  const DynamicAabbTree& tree() const { return tree_; }
  DynamicAabbTree& tree() { return tree_; }

 private:
  struct ProxyState {
    std::uint32_t body = 0;
    ProxyMotion motion = ProxyMotion::Static;
    bool active = true;
    bool touched = false;  // fat box or eligibility changed since the last findPairs
  };
  // Body ids ordered, proxy ids carried so stale pairs can be dropped.
  struct ProxyPair {
    std::uint32_t bodyA, bodyB;
    int proxyA, proxyB;
    auto operator<=>(const ProxyPair&) const = default;
  };

  // What one piece of the changed list's queries found. Kept between calls
  // so the lists keep their capacity. A cache line each: neighbouring pieces
  // run on different threads, and every pair found moves its list's end.
  struct alignas(64) QueryPiece {
    std::vector<ProxyPair> pairs;
    std::vector<int> stack;
    long long boxesTested = 0;
  };

  void touch(int proxy);
  bool drivesPairs(int proxy) const;
  void queryPiece(std::size_t begin, std::size_t end, QueryPiece& piece) const;
  long long queryChanged(int proxy, QueryPiece& piece) const;
  void queryAllChanged();
  void mergeFreshPairs();
  void writeBodyPairs(std::vector<BodyPair>& pairs) const;
  void orderForLocality();
  void requireProxy(int proxy, const char* operation) const;

  DynamicAabbTree tree_;
  const TaskSystem* tasks_ = nullptr;
  std::vector<ProxyState> proxies_;  // indexed by proxy id
  std::vector<int> changed_;
  std::vector<ProxyPair> pairs_;  // persistent, sorted
  std::vector<ProxyPair> fresh_;
  std::vector<ProxyPair> merged_;
  std::vector<QueryPiece> pieces_;
  std::vector<std::pair<std::uint32_t, int>> keyed_;  // Morton key, proxy
  BroadPhaseStats stats_;
  long long reinsertedSinceFind_ = 0;
};

}  // namespace physdbg
