#include "engine/broadphase/tree_broad_phase.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physdbg {

TreeBroadPhase::TreeBroadPhase(const DynamicAabbTreeOptions& options) : tree_(options) {}

void TreeBroadPhase::requireProxy(int proxy, const char* operation) const {
  if (!tree_.isProxy(proxy)) {
    throw std::invalid_argument(std::string("TreeBroadPhase::") + operation + ": " + std::to_string(proxy) +
                                " is not a live proxy");
  }
}

bool TreeBroadPhase::drivesPairs(int proxy) const {
  const ProxyState& state = proxies_[proxy];
  return state.motion == ProxyMotion::Dynamic && state.active;
}

void TreeBroadPhase::touch(int proxy) {
  if (proxies_[proxy].touched) return;
  proxies_[proxy].touched = true;
  changed_.push_back(proxy);
}

int TreeBroadPhase::addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) {
  const int proxy = tree_.createProxy(tightBox, body);
  if (proxy >= static_cast<int>(proxies_.size())) proxies_.resize(proxy + 1);
  // A reused id may still be listed as changed from its previous life; keep that flag.
  const bool touched = proxies_[proxy].touched;
  proxies_[proxy] = ProxyState{body, motion, true, touched};
  touch(proxy);
  return proxy;
}

void TreeBroadPhase::removeProxy(int proxy) {
  requireProxy(proxy, "removeProxy");
  touch(proxy);  // drops its pairs at the next findPairs
  tree_.destroyProxy(proxy);
}

void TreeBroadPhase::moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) {
  requireProxy(proxy, "moveProxy");
  if (tree_.moveProxy(proxy, tightBox, displacement)) {
    ++reinsertedSinceFind_;
    touch(proxy);
  }
}

void TreeBroadPhase::setProxyActive(int proxy, bool active) {
  requireProxy(proxy, "setProxyActive");
  if (proxies_[proxy].active == active) return;
  proxies_[proxy].active = active;
  touch(proxy);
}

// Collects the eligible pairs of one changed proxy. A pair of two changed
// proxies is taken from the lower id's query only.
void TreeBroadPhase::queryChanged(int proxy) {
  const Aabb& box = tree_.box(proxy);
  const bool drives = drivesPairs(proxy);
  const std::uint32_t body = proxies_[proxy].body;
  stack_.clear();
  stack_.push_back(tree_.root());
  while (!stack_.empty()) {
    const int node = stack_.back();
    stack_.pop_back();
    ++stats_.nodesVisited;
    ++stats_.boxesTested;
    if (!tree_.box(node).overlaps(box)) continue;
    if (!tree_.isLeaf(node)) {
      stack_.push_back(tree_.child2(node));
      stack_.push_back(tree_.child1(node));
      continue;
    }
    if (node == proxy || (proxies_[node].touched && node < proxy)) continue;
    const ProxyState& other = proxies_[node];
    if (other.body == body || (!drives && !drivesPairs(node))) continue;
    if (body < other.body) {
      fresh_.push_back({body, other.body, proxy, node});
    } else {
      fresh_.push_back({other.body, body, node, proxy});
    }
  }
}

void TreeBroadPhase::findPairs(std::vector<BodyPair>& pairs) {
  stats_ = BroadPhaseStats{};
  stats_.proxiesReinserted = reinsertedSinceFind_;
  reinsertedSinceFind_ = 0;
  fresh_.clear();
  std::sort(changed_.begin(), changed_.end());  // query order does not matter, but keep it reproducible
  for (const int proxy : changed_) {
    if (tree_.isProxy(proxy)) queryChanged(proxy);
  }
  std::sort(fresh_.begin(), fresh_.end());
  auto unchanged = [&](const ProxyPair& pair) {
    return !proxies_[pair.proxyA].touched && !proxies_[pair.proxyB].touched;
  };
  merged_.clear();
  merged_.reserve(pairs_.size() + fresh_.size());
  auto kept = pairs_.begin();
  auto added = fresh_.begin();
  while (kept != pairs_.end() || added != fresh_.end()) {
    if (kept != pairs_.end() && !unchanged(*kept)) {
      ++kept;
    } else if (added == fresh_.end() || (kept != pairs_.end() && *kept < *added)) {
      merged_.push_back(*kept++);
    } else {
      merged_.push_back(*added++);
    }
  }
  pairs_.swap(merged_);
  for (const int proxy : changed_) proxies_[proxy].touched = false;
  changed_.clear();
  pairs.clear();
  pairs.reserve(pairs_.size());
  for (const ProxyPair& pair : pairs_) {
    // Two proxies of the same two bodies make one body pair.
    if (pairs.empty() || pairs.back().a != pair.bodyA || pairs.back().b != pair.bodyB) {
      pairs.push_back({pair.bodyA, pair.bodyB});
    }
  }
}

}  // namespace physdbg
