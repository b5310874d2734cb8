#pragma once
// Bounds on the numbers a physdbg command line may ask for. The command runs
// unattended in CI on arguments and scene files written by other people, so
// every integer that sizes an allocation or a loop is checked against these
// before any work, with a UsageError (exit code 2) naming the argument.
// They are documented in README.md ("Limits"); change both together.
namespace physdbg::cli::limits {

// Steps one run may simulate: simulate/tree --steps, and for render and record
// (last frame) x --steps-per-frame. A scene's own `steps` is capped lower by
// the scene loader, so its default run always fits.
inline constexpr long long maxSteps = 100'000'000;
// Frame indices 0 .. maxFrames - 1: about 4.6 hours of 60 fps video.
inline constexpr int maxFrames = 1'000'000;
// Image sides (the renderer's own range) and pixels per image (256 MiB of RGBA).
inline constexpr int minImageSide = 16;
inline constexpr int maxImageSide = 16384;
inline constexpr long long maxImagePixels = 8192LL * 8192;
// tree --max-events: each event writes two images.
inline constexpr int maxTreeEvents = 10'000;
// Bodies --highlight takes: each gets an overlay line, so a screenful.
inline constexpr int maxHighlighted = 16;
// contacts --max-separation: metres, and the box pairs it may make the narrow
// phase test (each holds a result of about 100 bytes; a dense pile of
// 100,000 bodies touches in under a million).
inline constexpr double maxSeparation = 1e6;
inline constexpr long long maxSeparationPairs = 4'000'000;

}  // namespace physdbg::cli::limits
