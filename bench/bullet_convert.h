#pragma once
// Conversions to Bullet's single-precision types, for the peer benchmarks.
// Include only where PHYSDBG_HAVE_BULLET is defined.
#include <LinearMath/btVector3.h>

#include "engine/math.h"

namespace physdbg::bench {

inline btVector3 toBullet(const Vec3& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }

}  // namespace physdbg::bench
