#include "bench/tree_bullet_peer.h"

#include "bench/tree_bench_support.h"

#ifdef PHYSDBG_HAVE_BULLET
#include "bench/bullet_convert.h"
#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#endif

namespace physdbg::bench {

#ifdef PHYSDBG_HAVE_BULLET
namespace {

double surfaceArea(const btDbvtVolume& volume) {
  const btVector3 d = volume.Maxs() - volume.Mins();
  return 2.0 * (double(d.x()) * d.y() + double(d.y()) * d.z() + double(d.z()) * d.x());
}

// Walks btDbvt's nodes for the same quality figures as ours.
void measureTree(const btDbvtNode* node, int depth, PeerTreeFigures& figures) {
  if (node == nullptr) return;
  figures.height = std::max(figures.height, depth);
  if (node->isleaf()) return;
  figures.internalArea += surfaceArea(node->volume);
  measureTree(node->childs[0], depth + 1, figures);
  measureTree(node->childs[1], depth + 1, figures);
}

class BulletPeer final : public BulletBroadPhasePeer {
 public:
  explicit BulletPeer(const std::vector<Aabb>& boxes)
      : dispatcher_(&configuration_), indices_(boxes.size()) {
    proxies_.reserve(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      indices_[i] = static_cast<int>(i);
      proxies_.push_back(broadPhase_.createProxy(toBullet(boxes[i].min), toBullet(boxes[i].max), BOX_SHAPE_PROXYTYPE,
                                                 &indices_[i], btBroadphaseProxy::DefaultFilter,
                                                 btBroadphaseProxy::AllFilter, &dispatcher_));
    }
  }
  ~BulletPeer() override {
    for (btBroadphaseProxy* proxy : proxies_) broadPhase_.destroyProxy(proxy, &dispatcher_);
  }

  double step(const std::vector<Aabb>& boxes) override {
    return millisecondsOf([&] {
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        broadPhase_.setAabb(proxies_[i], toBullet(boxes[i].min), toBullet(boxes[i].max), &dispatcher_);
      }
      broadPhase_.calculateOverlappingPairs(&dispatcher_);
    });
  }

  std::vector<std::pair<int, int>> pairs() const override {
    std::vector<std::pair<int, int>> result;
    auto& cache = const_cast<btDbvtBroadphase&>(broadPhase_).getOverlappingPairCache()->getOverlappingPairArray();
    for (int i = 0; i < cache.size(); ++i) {
      const int a = *static_cast<const int*>(cache[i].m_pProxy0->m_clientObject);
      const int b = *static_cast<const int*>(cache[i].m_pProxy1->m_clientObject);
      result.emplace_back(std::min(a, b), std::max(a, b));
    }
    return result;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadPhase_;
  std::vector<int> indices_;  // proxies' user pointers point here: never resized after construction
  std::vector<btBroadphaseProxy*> proxies_;
};

}  // namespace

bool bulletAvailable() { return true; }

std::optional<PeerTreeFigures> bulletDbvtInsertRemove(const std::vector<Aabb>& boxes,
                                                      const std::vector<int>& removalOrder) {
  PeerTreeFigures figures;
  btDbvt tree;
  std::vector<btDbvtNode*> leaves(boxes.size());
  figures.insertMs = millisecondsOf([&] {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      leaves[i] = tree.insert(btDbvtVolume::FromMM(toBullet(boxes[i].min), toBullet(boxes[i].max)), nullptr);
    }
  });
  measureTree(tree.m_root, 0, figures);
  const double rootArea = tree.m_root != nullptr ? surfaceArea(tree.m_root->volume) : 0.0;
  figures.sar = rootArea > 0.0 ? figures.internalArea / rootArea : 0.0;
  figures.removeMs = millisecondsOf([&] {
    for (const int index : removalOrder) tree.remove(leaves[index]);
  });
  return figures;
}

std::unique_ptr<BulletBroadPhasePeer> BulletBroadPhasePeer::create(const std::vector<Aabb>& boxes) {
  return std::make_unique<BulletPeer>(boxes);
}

#else

bool bulletAvailable() { return false; }

std::optional<PeerTreeFigures> bulletDbvtInsertRemove(const std::vector<Aabb>&, const std::vector<int>&) {
  return std::nullopt;
}

std::unique_ptr<BulletBroadPhasePeer> BulletBroadPhasePeer::create(const std::vector<Aabb>&) { return nullptr; }

#endif

}  // namespace physdbg::bench
