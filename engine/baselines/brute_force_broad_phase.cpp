#include "engine/baselines/brute_force_broad_phase.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/parallel/task_system.h"

namespace physdbg {

BruteForceBroadPhase::BruteForceBroadPhase(const BruteForceOptions& options) : options_(options) {
  if (!(options.margin >= 0.0) || !std::isfinite(options.margin)) {
    throw std::invalid_argument("BruteForceBroadPhase: margin must be finite and >= 0");
  }
}

void BruteForceBroadPhase::requireProxy(int proxy, const char* operation) const {
  if (proxy < 0 || proxy >= static_cast<int>(slots_.size()) || !slots_[proxy].alive) {
    throw std::invalid_argument(std::string("BruteForceBroadPhase::") + operation + ": " + std::to_string(proxy) +
                                " is not a live proxy");
  }
}

int BruteForceBroadPhase::addProxy(const Aabb& tightBox, std::uint32_t body, ProxyMotion motion) {
  if (!tightBox.isValid()) throw std::invalid_argument("BruteForceBroadPhase::addProxy: invalid box");
  int proxy = static_cast<int>(slots_.size());
  if (freeSlots_.empty()) {
    slots_.emplace_back();
  } else {
    proxy = freeSlots_.back();
    freeSlots_.pop_back();
  }
  slots_[proxy] = Slot{tightBox.enlarged(options_.margin), body, motion, true, true};
  return proxy;
}

void BruteForceBroadPhase::removeProxy(int proxy) {
  requireProxy(proxy, "removeProxy");
  slots_[proxy].alive = false;
  freeSlots_.push_back(proxy);
}

void BruteForceBroadPhase::moveProxy(int proxy, const Aabb& tightBox, const Vec3& displacement) {
  requireProxy(proxy, "moveProxy");
  if (!tightBox.isValid() || !displacement.allFinite()) {
    throw std::invalid_argument("BruteForceBroadPhase::moveProxy: invalid box or displacement");
  }
  slots_[proxy].box = tightBox.enlarged(options_.margin);
}

void BruteForceBroadPhase::setProxyActive(int proxy, bool active) {
  requireProxy(proxy, "setProxyActive");
  slots_[proxy].active = active;
}

const Aabb& BruteForceBroadPhase::fatBox(int proxy) const {
  requireProxy(proxy, "fatBox");
  return slots_[proxy].box;
}

void BruteForceBroadPhase::findRowPairs(int i, Row& row) const {
  row.boxesTested = 0;
  row.pairs.clear();
  if (!slots_[i].alive) return;
  const int count = static_cast<int>(slots_.size());
  for (int j = options_.checkBothOrders ? 0 : i + 1; j < count; ++j) {
    if (j == i || !slots_[j].alive) continue;
    const Slot& first = slots_[i];
    const Slot& second = slots_[j];
    if (first.body == second.body || (!drivesPairs(first) && !drivesPairs(second))) continue;
    ++row.boxesTested;
    if (!first.box.overlaps(second.box) || j < i) continue;
    row.pairs.push_back({std::min(first.body, second.body), std::max(first.body, second.body)});
  }
}

void BruteForceBroadPhase::findPairs(std::vector<BodyPair>& pairs) {
  stats_ = BroadPhaseStats{};
  pairs.clear();
  rows_.resize(slots_.size());
  const auto findRows = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) findRowPairs(static_cast<int>(i), rows_[i]);
  };
  constexpr std::size_t rowGrain = 16;  // a row is up to n box tests
  if (options_.tasks) options_.tasks->parallelFor(slots_.size(), rowGrain, findRows);
  else findRows(0, slots_.size());
  for (const Row& row : rows_) {
    stats_.boxesTested += row.boxesTested;
    pairs.insert(pairs.end(), row.pairs.begin(), row.pairs.end());
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

}  // namespace physdbg
