#pragma once
// Which contact solver a world uses and how hard it works.
#include "engine/contacts/material_combine.h"

namespace physdbg {

enum class SolverKind {
  Seed,               // the design's one-point response (baselines/seed_solver.h)
  SequentialImpulse,  // manifolds, friction, soft contacts, substeps (sequential_impulse_solver.h)
};

// "seed" or "sequential_impulse": how scene files, --solver and bench
// records spell a kind.
inline const char* solverKindName(SolverKind kind) {
  return kind == SolverKind::Seed ? "seed" : "sequential_impulse";
}

// The seed solver's own parameter: the design's response, one contact at a time.
struct SeedSolverSettings {
  // Share of the penetration (beyond linearSlop) removed per step: the
  // design's editable position-correction damping. 1 removes it at once,
  // smaller is softer.
  double positionCorrection = 0.8;
};

struct SolverSettings {
  SolverKind kind = SolverKind::SequentialImpulse;

  // Both solvers.
  // Metres. Seed: the penetration left in place so a resting contact stays a
  // contact instead of flickering every step (the design's 5 mm allowance).
  // Sequential impulses: bodies this close count as touching (events, red
  // boxes), and contacts are built from 4 slops apart so resting pairs are
  // found before they touch.
  double linearSlop = 0.005;
  // Approach speeds below this (m/s) do not bounce: a resting body with
  // restitution would otherwise hop on gravity's dt*g every step.
  double restitutionThreshold = 0.2;
  // How a pair's restitution and friction combine; unset takes the solver's
  // default (material_combine.h).
  CombineRules combine;
  CombineRule restitutionCombine() const;
  CombineRule frictionCombine() const;

  SeedSolverSettings seed;

  // The sequential-impulse solver.
  // The step is cut into substeps; each integrates velocities, solves the
  // contacts `velocityIterations` times with soft position feedback,
  // integrates positions, then relaxes once without feedback. Substeps
  // converge much better than iterations for stacks (Catto, "Solver2D").
  int substeps = 8;
  int velocityIterations = 2;
  // A calm island takes at most calmSubsteps (Box2D v3's 4): half the
  // sweeps. Calm is a body resting alone on something immovable (a box on the
  // floor, a ball rolling down a ramp: no chain of contacts for many substeps
  // to carry a load along), or an island at rest: every body has begun the
  // last quarter second of steps in contact and slower than calmSpeed (m/s,
  // its spin's rim speed included), the masses span at most a factor of 10,
  // and no contact is deeper than twice what a resting contact settles at. A
  // stack at rest needs many substeps only to carry its weight down, and warm
  // starting already carries that from step to step. Bodies landing, sliding,
  // settling or pushed apart keep `substeps`, as do islands the resting-load
  // stiffening below has to stiffen. calmSubsteps = substeps turns this off.
  // Below 4, a calm island's contacts soften to a quarter of its substep rate
  // (2: 30 Hz), and it takes as many substeps as its load needs to settle
  // within restingOverlap: the 1000-box drop takes 13% fewer instructions
  // with 2, and a box alone rests 0.28 mm deep instead of 0.07 mm.
  int calmSubsteps = 4;
  double calmSpeed = 0.1;
  bool warmStarting = true;
  // Solve each colour's manifolds simd::width at a time in SIMD lanes
  // (wide_contact_rows.h); off, one by one in the same order. Same answer up
  // to rounding; the switch is there to compare them.
  bool wideContacts = true;
  // Soft contact: overlap is pushed out like a spring of this frequency
  // (never above a quarter of the substep rate, where it would ring) and
  // damping ratio, at most maxPushSpeed. Position error never becomes bounce:
  // a 25% overlap is undone in a few steps, calmly.
  double contactHertz = 60.0;
  double dampingRatio = 5.0;
  double maxPushSpeed = 3.0;  // m/s
  // A soft contact under load settles at (load / effective mass) g / omega^2
  // (resting_load.h; a contact that holds no weight up counts the force it
  // carried last step). When a contact would settle deeper than restingOverlap
  // (m), or than relativeRestingOverlap times the size of the smaller body
  // (the middle of its three extents), the step raises the contact frequency
  // to match and takes the substeps that frequency needs (a quarter of the
  // substep rate), up to maxSubsteps. Unit boxes in stacks and piles stay at
  // `substeps`; 10 kg on 0.1 kg stays at 8 but stiffens to 100 Hz; the
  // alternating 0.1/10 kg stack (30 kg on the bottom box) takes 12.
  // maxSubsteps = substeps turns this off.
  double restingOverlap = 0.0025;
  double relativeRestingOverlap = 0.02;
  int maxSubsteps = 32;
  // Tangential speeds below this (m/s) use static friction, above it dynamic.
  double stickingSpeed = 0.02;
  // Heavy on light: Gauss-Seidel hands a load down a chain of contacts at
  // about (light / heavy) per pass, so a body far heavier than the one it
  // rests on crushes it into the floor. Where a body rests on one more than
  // this many times lighter (nearer the ground by contacts, or as near and
  // lighter: a light box a heavy one presses into a wall), that contact
  // treats the lower body as only this many times lighter (mass scaling, as
  // in shock propagation): the stack holds, the lower body feels less of the
  // weight in that contact alone. 0 turns it off.
  double massRatioLimit = 100.0;
};

inline CombineRule SolverSettings::restitutionCombine() const {
  return combine.restitution.value_or(kind == SolverKind::Seed ? CombineRule::Average : CombineRule::Maximum);
}

inline CombineRule SolverSettings::frictionCombine() const {
  return combine.friction.value_or(kind == SolverKind::Seed ? CombineRule::Average : CombineRule::GeometricMean);
}

// The substeps of a step of dt for a body in flight under the sequential-
// impulse solver: `substeps`, or as many as a contact at contactHertz needs
// (a substep rate four times it, the rule every contact island follows), up
// to maxSubsteps. So a body that lands integrates with the same h before,
// during and after its landing step.
int flightSubstepCount(const SolverSettings& settings, double dt);

}  // namespace physdbg
