#pragma once
// libccd (double build) as the narrow-phase peer, fed the same support
// functions as our colliders so both sides answer the same geometric question.
#include "engine/colliders/collider.h"

namespace physdbg::bench {

enum class CcdMethod { GjkEpa, Mpr };

struct PeerContact {
  bool hit = false;
  double depth = 0.0;
  Vec3 normal = Vec3::Zero();
};

// False when the benchmarks were built without libccd.
bool ccdAvailable();

const char* ccdMethodName(CcdMethod method);

PeerContact ccdPenetration(CcdMethod method, const Collider& a, const Transform& ta, const Collider& b,
                           const Transform& tb);

}  // namespace physdbg::bench
