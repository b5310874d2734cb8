#pragma once
// Expanding polytope on the cores of two overlapping support shapes. The
// polytope lives in fixed-capacity arrays on the stack: no allocation.
#include "engine/narrowphase/gjk.h"

namespace physdbg {

struct EpaResult {
  Vec3 normal = Vec3::UnitY();  // from A to B: moving B by depth * normal separates the cores
  double depth = 0.0;           // of the cores; about 0 (or slightly below) when only touching
  Vec3 pointA = Vec3::Zero();
  Vec3 pointB = Vec3::Zero();
  int iterations = 0;
};

inline constexpr int kEpaFaceCapacity = 512;

// Grows GJK's simplex to a full tetrahedron when it has fewer than 4
// independent points (touching, flat or zero-size shapes), then expands:
// every face that sees the new support point goes and the horizon is closed
// to it. Stops when the support point gains less than the tolerance over the
// closest face, when it cannot grow, or when the face budget is spent.
EpaResult runEpa(const Simplex& start, SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options);

}  // namespace physdbg
