#include "engine/broadphase/tree_broad_phase.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "engine/parallel/task_system.h"

namespace physdbg {

namespace {

// Changed proxies per piece of the parallel queries. A query costs a few
// hundred nanoseconds, so a piece is tens of microseconds: well above what
// handing it to another thread costs.
constexpr std::size_t queryPieceSize = 64;

}  // namespace

TreeBroadPhase::TreeBroadPhase(const DynamicAabbTreeOptions& options, const TaskSystem* tasks)
    : tree_(options), tasks_(tasks) {}

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
// proxies is taken from the lower id's query only. Both children of a node
// are tested where the node comes off the stack: their two boxes load side by
// side instead of one after the other, and only overlapping internal nodes
// are pushed. The stack never holds more than the tree's height plus one
// node, so it is sized once (queryPiece) and indexed without checks. Returns
// the boxes tested (the root, and both children of every overlapping internal
// node).
long long TreeBroadPhase::queryChanged(int proxy, QueryPiece& piece) const {
  const Aabb box = tree_.box(proxy);
  const int root = tree_.root();
  if (tree_.isLeaf(root) || !overlapping(tree_.box(root), box)) return 1;  // a lone root is this proxy
  int* const stack = piece.stack.data();
  std::vector<ProxyPair>& found = piece.pairs;
  const ProxyState self = proxies_[proxy];
  const bool drives = drivesPairs(proxy);
  const auto report = [&](int other) {
    if (other == proxy) return;
    const ProxyState& state = proxies_[other];
    if ((state.touched && other < proxy) || state.body == self.body) return;
    if (!drives && !(state.motion == ProxyMotion::Dynamic && state.active)) return;
    if (self.body < state.body) {
      found.push_back({self.body, state.body, proxy, other});
    } else {
      found.push_back({state.body, self.body, other, proxy});
    }
  };
  long long tested = 1;
  int top = 0;
  stack[top++] = root;
  while (top > 0) {
    const int node = stack[--top];
    const int first = tree_.child1(node), second = tree_.child2(node);
    const bool overlapsFirst = overlapping(tree_.box(first), box);
    const bool overlapsSecond = overlapping(tree_.box(second), box);
    tested += 2;
    if (overlapsSecond) {
      if (tree_.isLeaf(second)) {
        report(second);
      } else {
        stack[top++] = second;
      }
    }
    if (overlapsFirst) {
      if (tree_.isLeaf(first)) {
        report(first);
      } else {
        stack[top++] = first;
      }
    }
  }
  return tested;
}

namespace {

// Spreads the low 10 bits of value to every third bit.
std::uint32_t spreadBits(std::uint32_t value) {
  value &= 0x3ff;
  value = (value | (value << 16)) & 0x030000ff;
  value = (value | (value << 8)) & 0x0300f00f;
  value = (value | (value << 4)) & 0x030c30c3;
  value = (value | (value << 2)) & 0x09249249;
  return value;
}

}  // namespace

// Queries of nearby proxies walk the same nodes: visiting them in Morton order
// keeps those nodes in cache. Ties fall back to the proxy id, so the order is
// reproducible (the pair set does not depend on it anyway).
void TreeBroadPhase::orderForLocality() {
  keyed_.clear();
  if (tree_.root() == DynamicAabbTree::nullNode) return;
  const Aabb& bounds = tree_.box(tree_.root());
  const Vec3 scale = (bounds.max - bounds.min).cwiseMax(Vec3::Constant(1e-300)).cwiseInverse() * 1023.0;
  for (const int proxy : changed_) {
    std::uint32_t key = 0;
    if (tree_.isProxy(proxy)) {
      const Vec3 cell = ((tree_.box(proxy).center() - bounds.min).cwiseProduct(scale)).cwiseMax(0.0).cwiseMin(1023.0);
      key = spreadBits(static_cast<std::uint32_t>(cell.x())) | (spreadBits(static_cast<std::uint32_t>(cell.y())) << 1) |
            (spreadBits(static_cast<std::uint32_t>(cell.z())) << 2);
    }
    keyed_.emplace_back(key, proxy);
  }
  std::sort(keyed_.begin(), keyed_.end());
  for (std::size_t i = 0; i < keyed_.size(); ++i) changed_[i] = keyed_[i].second;
}

void TreeBroadPhase::queryPiece(std::size_t begin, std::size_t end, QueryPiece& piece) const {
  piece.pairs.clear();
  piece.boxesTested = 0;
  const std::size_t depthBound = static_cast<std::size_t>(std::max(tree_.height(), 0)) + 2;
  if (piece.stack.size() < depthBound) piece.stack.resize(2 * depthBound);
  for (std::size_t i = begin; i < end; ++i) {
    const int proxy = changed_[i];
    if (tree_.isProxy(proxy)) piece.boxesTested += queryChanged(proxy, piece);
  }
}

// The queries only read the tree and the proxies' flags, so pieces run side
// by side. The pieces are fixed by the list's length alone, and their pairs
// are sorted afterwards, so the thread count changes nothing but the time.
void TreeBroadPhase::queryAllChanged() {
  const bool parallel = tasks_ != nullptr && tasks_->threadCount() > 1 &&
                        changed_.size() >= static_cast<std::size_t>(parallelQueryMinimum);
  const std::size_t pieceCount = parallel ? (changed_.size() + queryPieceSize - 1) / queryPieceSize : 1;
  if (pieces_.size() < pieceCount) pieces_.resize(pieceCount);
  if (parallel) {
    tasks_->parallelFor(pieceCount, 1, [&](std::size_t begin, std::size_t end) {
      for (std::size_t piece = begin; piece < end; ++piece) {
        queryPiece(piece * queryPieceSize, std::min(changed_.size(), (piece + 1) * queryPieceSize), pieces_[piece]);
      }
    });
  } else {
    queryPiece(0, changed_.size(), pieces_[0]);
  }
  for (std::size_t piece = 0; piece < pieceCount; ++piece) stats_.nodesVisited += pieces_[piece].boxesTested;
  if (pieceCount == 1) {
    fresh_.swap(pieces_[0].pairs);  // the buffers trade places, keeping both capacities
    return;
  }
  fresh_.clear();
  for (std::size_t piece = 0; piece < pieceCount; ++piece) {
    fresh_.insert(fresh_.end(), pieces_[piece].pairs.begin(), pieces_[piece].pairs.end());
  }
}

void TreeBroadPhase::findPairs(std::vector<BodyPair>& pairs) {
  stats_ = BroadPhaseStats{};
  stats_.proxiesReinserted = reinsertedSinceFind_;
  reinsertedSinceFind_ = 0;
  orderForLocality();
  queryAllChanged();
  stats_.boxesTested = stats_.nodesVisited;  // one box test per visited node
  std::sort(fresh_.begin(), fresh_.end());
  mergeFreshPairs();
  for (const int proxy : changed_) proxies_[proxy].touched = false;
  changed_.clear();
  writeBodyPairs(pairs);
}

// The caller's list usually holds last step's pairs, and other threads read
// it every step (the world screens its pairs in parallel). Storing a value
// takes its cache line back from every core that read it, so an entry is
// only stored where it changed: a world at rest rewrites nothing. On two
// cores that made the pairs stage of a 1000-sphere drop at rest (10308 pairs)
// two to three times cheaper.
void TreeBroadPhase::writeBodyPairs(std::vector<BodyPair>& pairs) const {
  std::size_t written = 0;
  for (const ProxyPair& proxyPair : pairs_) {
    const BodyPair pair{proxyPair.bodyA, proxyPair.bodyB};
    // Two proxies of the same two bodies make one body pair.
    if (written > 0 && pairs[written - 1] == pair) continue;
    if (written == pairs.size()) {
      pairs.push_back(pair);
    } else if (pairs[written] != pair) {
      pairs[written] = pair;
    }
    ++written;
  }
  pairs.resize(written);
}

// Persistent pairs of two unchanged proxies stay (their boxes and eligibility
// did not change); every pair with a changed proxy comes from this call's
// queries. Both lists are sorted, so a merge keeps the result sorted.
void TreeBroadPhase::mergeFreshPairs() {
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
}

}  // namespace physdbg
