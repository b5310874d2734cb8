#pragma once
// The design's demonstration scenes (balls in an enclosure, a bounce test),
// kept apart from the other built-in scenes so `physdbg bench seed` can run
// exactly the set the design's frame rates were quoted for.
#include <vector>

#include "scenes/scene.h"

namespace physdbg {

// balls24, balls48, balls48_bruteforce, balls48_no_static_skip,
// balls48_bruteforce_no_static_skip and bounce, in that order.
std::vector<BuiltinScene> designScenes();

}  // namespace physdbg
