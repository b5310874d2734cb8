#include "cli/overlapping_pairs.h"

#include <algorithm>
#include <cstdint>

#include "engine/broadphase/dynamic_aabb_tree.h"

namespace physdbg::cli {

std::vector<BodyPair> overlappingPairs(const std::vector<Aabb>& boxes, std::size_t most) {
  DynamicAabbTreeOptions options;
  options.margin = 0.0;  // leaves hold the tight boxes themselves, so the test is the same as box against box
  DynamicAabbTree tree(options);
  for (std::size_t i = 0; i < boxes.size(); ++i) tree.createProxy(boxes[i], static_cast<std::uint32_t>(i));
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < boxes.size() && pairs.size() <= most; ++i) {
    const auto a = static_cast<std::uint32_t>(i);
    tree.query(boxes[i], [&](int proxy) {
      const std::uint32_t b = tree.userData(proxy);
      if (b > a) pairs.push_back({a, b});
      return pairs.size() <= most;
    });
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace physdbg::cli
