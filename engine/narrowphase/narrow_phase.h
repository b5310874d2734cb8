#pragma once
// Entry point of the narrow phase for one candidate pair.
#include "engine/colliders/collider.h"
#include "engine/narrowphase/narrow_phase_options.h"

namespace physdbg {

// Sphere-sphere and box-sphere use closed forms unless
// options.analyticFastPaths is false; box-box uses separating axes unless
// options.boxBoxSat is false (GJK only for a separated pair whose distance no
// axis gives); every other pair runs GJK on the shape cores and, when they
// overlap, EPA. Throws std::invalid_argument for
// non-finite transforms or options that cannot work (non-positive limits,
// negative tolerances).
ContactResult collide(const Collider& a, const Transform& ta, const Collider& b, const Transform& tb,
                      const NarrowPhaseOptions& options = {});

}  // namespace physdbg
