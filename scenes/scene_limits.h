#pragma once
// Bounds on what a scene file may ask for. Scene files come from other people
// and run unattended in CI, so every size that drives an allocation or a loop
// is checked against these before anything is built. They are documented in
// scenes/README.md ("Limits"); change both together.
#include <cstddef>
#include <cstdint>

namespace physdbg::scene_limits {

inline constexpr std::uintmax_t maxFileBytes = 64u << 20;  // 64 MiB of JSON
inline constexpr int maxNesting = 32;                       // arrays and objects inside each other
inline constexpr long long maxBodies = 100'000;  // after `repeat`; a touching pile costs ~5 KB a body
inline constexpr std::size_t maxBodyNameLength = 64;  // a body's "name": a label, not a document
inline constexpr std::size_t maxHullPoints = 100'000;       // per convex shape
// Per triangle mesh: a big level, and about 1 GB built (vertices 24 B,
// triangles 12 B, normals 24 B, hierarchy ~30 B a triangle).
inline constexpr std::size_t maxMeshVertices = 10'000'000;
inline constexpr std::size_t maxMeshTriangles = 10'000'000;
inline constexpr std::uintmax_t maxMeshFileBytes = std::uintmax_t{1} << 30;  // a mesh file Assimp reads
inline constexpr std::size_t maxMeshNodes = 10'000;  // names in a mesh's "nodes"
// Samples of one heightfield: 8192 x 8192, 256 MiB at 4 bytes a sample.
inline constexpr std::uint64_t maxHeightfieldSamples = 8192ull * 8192ull;
inline constexpr long long maxSteps = 10'000'000;
inline constexpr std::size_t maxForces = 10'000;  // "forces" entries: each is looked at every step
inline constexpr std::size_t maxStates = 10'000;  // "set" entries: each is looked at every step
// "threads": each is a oneTBB worker with its own stack; more than a big
// machine has only costs memory (the result is the same for any count).
inline constexpr int maxThreads = 256;
inline constexpr int maxSubsteps = 1000;
inline constexpr int maxIterations = 1000;
inline constexpr long long maxSweepsPerStep = 10'000;  // max_substeps x iterations
inline constexpr double minDt = 1e-6, maxDt = 1.0;     // seconds
inline constexpr double maxFatMargin = 1e3;             // m: past this every box overlaps every other
// Every other number: finite, |x| <= maxMagnitude; sizes and masses >= minSize.
inline constexpr double maxMagnitude = 1e9;
inline constexpr double minSize = 1e-9;
inline constexpr std::size_t maxEchoedChars = 48;  // of a value or key quoted in a message

}  // namespace physdbg::scene_limits
