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
// independent points (touching, flat or zero-size shapes), then expands: the
// closest face and the faces that see the new support point connected to it
// go (found by walking across edges, not by testing every face), and their
// border is closed to the point. Stops when the support point gains less
// than the tolerance over the closest face, when it cannot grow (the face
// budget is spent, or rounding leaves a border that is not one loop), and
// reports the closest face so far.
EpaResult runEpa(const Simplex& start, SupportShape& a, SupportShape& b, const NarrowPhaseOptions& options);

}  // namespace physdbg
