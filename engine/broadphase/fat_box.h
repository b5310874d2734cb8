#pragma once
// The fat-box rule of the broad phase, apart from the tree: a broad phase
// that keeps its own fat boxes (the GPU one) must enlarge them exactly as the
// tree does, or the two would report different pairs for the same moves.
#include "engine/aabb.h"

namespace physdbg {

// The tight box enlarged by the margin on every side and stretched only
// towards the motion (a body keeps going the way it went). A new proxy has
// no motion yet: a zero displacement.
inline Aabb fattenBox(const Aabb& tight, const Vec3& displacement, double margin, double velocityPrediction) {
  Aabb fat = tight.enlarged(margin);
  const Vec3 ahead = velocityPrediction * displacement;
  fat.min += ahead.cwiseMin(Vec3::Zero());
  fat.max += ahead.cwiseMax(Vec3::Zero());
  return fat;
}

}  // namespace physdbg
