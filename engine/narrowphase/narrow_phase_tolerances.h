#pragma once
// The box-box test's and box-box manifold's tolerances, in one place: the
// GPU's narrow-phase shader is generated with these values (gpu/
// narrow_phase_shader.cpp), so it takes the CPU's decisions and cannot drift.
namespace physdbg::tolerances {

// Below this sine between an edge of A and an edge of B their cross product
// is not tried as an axis. A nearly parallel pair gives a direction whose
// separation carries round-off of about epsilon * size / sine, while leaving
// the axis out errs by about sine * size (for exactly parallel edges the face
// axes suffice); the two balance near sqrt(epsilon), 1e-8.
inline constexpr double parallelSine = 1e-8;
// Relative to the pair's size. Boxes sitting squarely on each other make
// axes tie in exact arithmetic (an edge cross product is then a face normal),
// and round-off would pick among them at random from step to step. Within
// this margin a face of A beats a face of B, and a face beats an edge pair,
// so resting stacks report a face normal. Kept far below EPA's tolerance
// (1e-9 of the pair's size): a real edge contact is never traded for a face.
inline constexpr double tieTolerance = 1e-10;
// Relative to the pair's size: how much the witness points' gap may exceed
// the axis's separation and still prove it is the distance.
inline constexpr double witnessTolerance = 1e-10;
// Relative; far above round-off in the areas the box-box manifold's point
// reduction compares, far below any difference that matters to which points
// hold the box up.
inline constexpr double reductionTieMargin = 1e-9;

}  // namespace physdbg::tolerances
