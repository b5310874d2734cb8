#pragma once
// The weight each contact holds up when everything rests, found by walking
// the bodies from the top down. The solver uses it twice:
//
// - Stiffness. A soft contact settles at (load / effective mass) g / omega^2.
//   A light box under heavy ones has a tiny effective mass, so at the usual
//   stiffness it sinks centimetres (2 cm under 30 kg on 0.1 kg at 60 Hz).
//   The solver raises the stiffness, and the substeps that make it safe,
//   until the most loaded contact settles within its target.
// - Warm start for new contacts. Gauss-Seidel passes load down a stack one
//   contact at a time, and a light body between heavy ones hands on only
//   about (light / heavy) of the missing impulse per sweep. A new stack starts
//   from zero impulse, so its heavy bodies sink for several steps before the
//   impulse builds up. Starting a new contact at the load it will carry puts
//   the solve near its answer; the solver still corrects any error in it.
#include <vector>

#include <utility>

#include "engine/contacts/contact_manifold.h"
#include "engine/dynamics/rigid_body.h"
#include "engine/solver/movable_bodies.h"
#include "engine/math.h"

namespace physdbg {

// Per manifold, the mass (kg) it supports along its normal. A manifold
// supports the upper body when its normal is within 45 degrees of `up` and
// one of its points touches (separation at most touching[manifold]). Each
// movable body, highest first, passes its own mass plus what rests on it to
// its supports, split evenly; a movable supporter passes it on in turn.
// Manifolds that hold nothing up (walls, sides, bodies in free flight) get 0.
// With `massScales` (per manifold, the factors on a's and b's inverse mass,
// sequential_impulse_solver.h), a supporter passes on only the part of a load
// its scaled contact lets reach it.
std::vector<double> restingLoads(const std::vector<RigidBody>& bodies, const MovableBodies& movable,
                                 const std::vector<ContactManifold>& manifolds, const std::vector<double>& touching,
                                 const Vec3& up, const std::vector<std::pair<double, double>>* massScales = nullptr);

// Points that touch share a manifold's load.
int touchingPoints(const ContactManifold& manifold, double touching);

// A manifold with no impulse at all (new this step) that holds a load gets
// it as its normal impulse for one substep of length h, shared by its
// touching points. A manifold that carries impulse from the last step keeps it.
void seedNewContact(ContactManifold& manifold, double load, double touching, double gravity, double h);

}  // namespace physdbg
