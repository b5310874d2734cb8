#pragma once
// What a world is made with (WorldSettings) and what its last step did
// (StepStats): plain values, so a scene parser, a report or a bench that
// only describes or reads a world includes this, not the engine's stages.
#include "engine/broadphase/broad_phase.h"
#include "engine/broadphase/tree_options.h"
#include "engine/math.h"
#include "engine/narrowphase/narrow_phase_options.h"
#include "engine/solver/solver_settings.h"
#include "engine/step_profile.h"

namespace physdbg {

// Where a world's collision detection runs (scene key "collision").
enum class CollisionDevice { Cpu, Gpu };
const char* collisionDeviceName(CollisionDevice device);

enum class BroadPhaseKind { Tree, BruteForce };

struct WorldSettings {
  Vec3 gravity{0.0, -9.81, 0.0};
  double dt = 1.0 / 60.0;

  BroadPhaseKind broadPhase = BroadPhaseKind::Tree;
  double fatMargin = 0.1;               // m added around each tight box
  // The tree's insertion and rotations (dynamic_aabb_tree.h), so renders and
  // benches can compare them on the same scene.
  InsertionMethod treeInsertion = InsertionMethod::BranchAndBound;
  bool treeRotations = true;
  bool bruteForceBothOrders = false;    // the design's baseline: test A-B and B-A
  // The design skips pairs of bodies that cannot move (static-static). Off
  // reproduces its slower baseline: those pairs go through the narrow phase too.
  bool skipStaticPairs = true;
  // A resting pair whose bodies stayed within a tenth of a millimetre of
  // where its contact was last computed takes that contact again, carried
  // along with the bodies (contact_reuse.h): 9.5% fewer instructions on 300
  // steps of the 1000-box drop. Scene key collision.reuse_contacts; off, every
  // pair is tested anew each step (to compare against, or to rule it out).
  bool reuseContacts = true;

  // A pair apart at the start of the step whose bodies close by more than a
  // quarter of the smaller one's size in the step is cast along its motion
  // (narrowphase/linear_cast.h): its contact takes the normal and points of
  // the time of impact. Scene key time_of_impact.
  bool castFastPairs = true;

  bool allowSleep = true;
  double sleepLinearSpeed = 0.05;   // m/s
  double sleepAngularSpeed = 0.05;  // rad/s
  double timeToSleep = 0.5;         // s below both speeds before sleeping

  // Threads the step may use: 0 one per hardware thread, 1 none spawned. The
  // states are bit-identical for every count.
  int threads = 0;

  SolverSettings solver;  // sequential impulses by default; solver.seed for the design's
  NarrowPhaseOptions narrowPhase;

  // Gpu: the broad phase and the pairs the offload handles run in compute
  // shaders (gpu/); the world must then be given a CollisionOffload.
  CollisionDevice collisionDevice = CollisionDevice::Cpu;
};

// Work done by the last step, for reports and overlays: counters, not claims.
struct StepStats {
  int awakeBodies = 0;
  int sleepingBodies = 0;
  int lockedBodies = 0;  // awake bodies with an axis lock: the only ones that do lock work
  int candidatePairs = 0;  // after the collision filters
  int filteredPairs = 0;   // pairs the broad phase found that the bodies' filters keep apart
  int boundsRejected = 0;  // candidate pairs whose tight boxes were too far apart for the narrow phase
  int staticPairsTested = 0;
  int contacts = 0;
  int responses = 0;
  int manifolds = 0;
  int manifoldPoints = 0;
  double largestPenetration = 0;  // after the step, m
  int substeps = 0;               // sequential impulses: the most substeps any island took
  double contactHertz = 0;        // sequential impulses: the stiffest contact frequency any island used
  NarrowPhaseCounters narrowPhase;
  BroadPhaseStats broadPhase;
  StepProfile profile;  // seconds per stage (step_profile.h)
};

}  // namespace physdbg
