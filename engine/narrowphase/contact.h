#pragma once
// What the narrow phase reports for one pair. Conventions: the normal points
// from A to B; moving B by depth * normal separates the pair; pointA is A's
// deepest point inside B (or A's closest point when separated) and pointB is
// B's, both in world space.
#include "engine/math.h"

namespace physdbg {

enum class ContactStatus { Separated, Touching, Penetrating };

const char* contactStatusName(ContactStatus status);

struct ContactResult {
  ContactStatus status = ContactStatus::Separated;
  double distance = 0.0;  // > 0 when separated, 0 otherwise
  Vec3 normal = Vec3::UnitY();
  double depth = 0.0;  // > 0 when penetrating, 0 otherwise
  Vec3 pointA = Vec3::Zero();
  Vec3 pointB = Vec3::Zero();
  int gjkIterations = 0;
  int epaIterations = 0;
  bool usedGeneralPath = false;
};

struct NarrowPhaseOptions {
  // Signed distances within +-touchingTolerance (metres) are reported as
  // Touching with depth 0. 1e-6 m sits far above double rounding for scenes
  // 1e5 m from the origin (about 1e-11 m) and far below anything a solver's
  // slop or a viewer can see, so resting contacts are neither lost to a
  // 1e-12 gap nor turned into deep contacts.
  double touchingTolerance = 1e-6;
  // GJK and EPA stop when the next support point gains less than this,
  // relative to the size of the pair (shapes' bounding radii).
  double relativeTolerance = 1e-12;
  int maxGjkIterations = 64;
  // Triangles the EPA polytope may hold (capped at kEpaFaceCapacity = 512);
  // when spent, the closest face so far is reported (a lower bound on depth).
  int maxEpaFaces = 256;
  bool analyticFastPaths = true;
};

// Per-pair tallies the world sums for its report; no global counters.
struct NarrowPhaseCounters {
  long long pairs = 0;
  long long fastPath = 0;
  long long gjk = 0;
  long long epa = 0;

  void add(const ContactResult& result) {
    ++pairs;
    if (!result.usedGeneralPath) ++fastPath;
    if (result.gjkIterations > 0) ++gjk;
    if (result.epaIterations > 0) ++epa;
  }
};

}  // namespace physdbg
