#pragma once
// The broad phase: which body pairs the narrow phase must test. The world holds
// one implementation behind this interface so the tree and the brute-force
// baseline can be swapped and compared on the same scene.
#include <compare>
#include <cstdint>
#include <vector>

#include "engine/aabb.h"

namespace physdbg {

enum class ProxyMotion { Static, Dynamic };

struct BodyPair {
  std::uint32_t a, b;  // a < b
  auto operator<=>(const BodyPair&) const = default;
};

// Work counters of the last findPairs (tests, visits) and of the moves since
// the previous findPairs (reinsertions).
struct BroadPhaseStats {
  long long boxesTested = 0;
  long long nodesVisited = 0;
  long long proxiesReinserted = 0;
};

class BroadPhase {
 public:
  virtual ~BroadPhase() = default;
  virtual int addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) = 0;
  virtual void removeProxy(int proxy) = 0;
  // Called every step for awake dynamic bodies; displacement is this step's motion (for velocity prediction).
  virtual void moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) = 0;
  // Sleeping bodies are inactive: they never make pairs with static or other inactive proxies.
  virtual void setProxyActive(int proxy, bool active) = 0;
  // Every pair whose fat boxes overlap and where at least one proxy is dynamic and active, each once, sorted by (a, b).
  virtual void findPairs(std::vector<BodyPair>& pairs) = 0;
  virtual const Aabb& fatBox(int proxy) const = 0;
  virtual BroadPhaseStats stats() const = 0;
};

}  // namespace physdbg
