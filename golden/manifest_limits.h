#pragma once
// Bounds on what a golden manifest may ask for. Manifests come from other
// people and run unattended in CI, so every number that sizes an allocation,
// a loop or a simulation is checked against these before any work, with an
// error naming the file and the key (exit code 2), in the style of
// cli/limits.h. They are documented in README.md ("physdbg golden"); change
// both together.
#include <cstdint>

namespace physdbg::golden::limits {

// The manifest file itself is read whole.
inline constexpr std::uintmax_t maxManifestBytes = 1 << 20;
inline constexpr int maxCases = 256;
inline constexpr int maxFramesPerCase = 64;
// Frame indices 0..maxFrameIndex: frame N simulates N steps first.
inline constexpr int maxFrameIndex = 100'000;
// Approved frames are committed to repositories and three pictures of each
// failure go into the report: small sides, at most 2048 x 2048 pixels.
inline constexpr int minImageSide = 16;
inline constexpr int maxImageSide = 4096;
inline constexpr long long maxImagePixels = 2048LL * 2048;
// Case names become folder and file names: [A-Za-z0-9_.-], no leading '.'.
inline constexpr int maxCaseNameLength = 64;

}  // namespace physdbg::golden::limits
