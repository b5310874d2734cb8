#pragma once
// How hard the narrow phase works and what it counts; kept apart from the
// contact types so the solvers need not see the narrow phase's knobs.
#include "engine/contacts/contact.h"

namespace physdbg {

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
  // Box against box by separating axes (box_box_contact.h) instead of GJK +
  // EPA; off, box pairs take the general path exactly as before it existed.
  bool boxBoxSat = true;
};

// Per-pair tallies the world sums for its report; no global counters.
struct NarrowPhaseCounters {
  long long pairs = 0;
  long long fastPath = 0;
  long long gjk = 0;
  long long epa = 0;
  long long boxBox = 0;  // box pairs the separating-axis test ran on (some then also ran GJK)
  long long reused = 0;  // pairs that took their last answer again (contact_reuse.h), no test run
  long long meshTriangles = 0;  // triangles of meshes tested against bodies (mesh_contacts.h)
  long long meshCorrected = 0;  // of their contacts, those on an inactive edge given the face normal

  void add(const ContactResult& result) {
    ++pairs;
    if (!result.usedGeneralPath && !result.usedBoxBox) ++fastPath;
    if (result.usedBoxBox) ++boxBox;
    if (result.gjkIterations > 0) ++gjk;
    if (result.epaIterations > 0) ++epa;
  }
  void addReused() {
    ++pairs;
    ++reused;
  }
  NarrowPhaseCounters& operator+=(const NarrowPhaseCounters& other) {
    pairs += other.pairs;
    fastPath += other.fastPath;
    gjk += other.gjk;
    epa += other.epa;
    boxBox += other.boxBox;
    reused += other.reused;
    meshTriangles += other.meshTriangles;
    meshCorrected += other.meshCorrected;
    return *this;
  }
};

}  // namespace physdbg
