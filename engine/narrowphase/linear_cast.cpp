#include "engine/narrowphase/linear_cast.h"

namespace physdbg {

std::optional<LinearCastHit> linearCast(const Collider& a, const Transform& ta, const Vec3& motionA, const Collider& b,
                                        const Transform& tb, const Vec3& motionB, double tolerance,
                                        const NarrowPhaseOptions& options) {
  const Vec3 closingMotion = motionA - motionB;
  double fraction = 0.0;
  for (int advance = 0; advance < 32; ++advance) {
    LinearCastHit hit{fraction, {}, {ta.position + fraction * motionA, ta.rotation},
                      {tb.position + fraction * motionB, tb.rotation}};
    hit.result = collide(a, hit.a, b, hit.b, options);
    if (hit.result.status != ContactStatus::Separated || hit.result.distance <= tolerance) return hit;
    // The normal points from a to b: the distance shrinks at this rate.
    const double closing = closingMotion.dot(hit.result.normal);
    if (!(closing > 0.0)) return std::nullopt;
    fraction += hit.result.distance / closing;
    if (!(fraction <= 1.0)) return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace physdbg
