#pragma once
// Which bodies' tight world boxes overlap, for `physdbg contacts`: a dynamic
// AABB tree over the boxes, queried once per body, so a scene of n bodies
// costs O(n log n) plus the pairs found instead of n^2 / 2 box tests (71 s
// for 100k bodies). Static pairs are included: the command inspects a
// configuration, it does not skip what a step would skip.
#include <cstddef>
#include <limits>
#include <vector>

#include "engine/aabb.h"
#include "engine/broadphase/broad_phase.h"

namespace physdbg::cli {

// Every pair (a, b), a < b indices into `boxes`, whose boxes overlap
// (Aabb::overlaps: touching faces count), each once, sorted by (a, b). Past
// `most` pairs it stops and returns more than `most` of them (not all).
std::vector<BodyPair> overlappingPairs(const std::vector<Aabb>& boxes,
                                       std::size_t most = std::numeric_limits<std::size_t>::max());

}  // namespace physdbg::cli
