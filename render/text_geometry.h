#pragma once
// Screen-space text from stb_easy_font: each glyph is a set of axis-aligned
// quads on a one-unit grid; scaled and rounded to whole pixels they stay crisp.
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "debugdraw/primitives.h"
#include "render/frame_batches.h"

namespace physdbg::render {

// Each character costs up to 11 quads (about 5.5 KiB with its outline on
// average), so both functions bound what they build: a text longer than
// debugdraw::maxTextCharacters, or `triangles` that would outgrow the geometry
// of debugdraw::maxFrameTextCharacters characters (glyphs and outlines), are
// refused with std::invalid_argument. Use one `triangles` vector per frame.

// Glyph quads as two triangles each, in the text's colour. Throws
// std::invalid_argument for a non-positive or non-finite scale or position,
// or beyond the limits above.
void appendText(const debugdraw::Text& text, std::vector<TextVertex>& triangles);

// A dark outline (the glyphs offset one step in eight directions) so text reads
// on light and dark backgrounds alike. Draw it before the glyphs. Same checks.
void appendTextOutline(const debugdraw::Text& text, std::vector<TextVertex>& triangles);

// A world-anchored label's text: centred horizontally on `anchor` (pixels from
// the top-left corner, where the renderer projected the label's position), its
// last baseline kLabelGapPixels above it, so the text sits just over what it names.
inline constexpr float kLabelGapPixels = 4;
debugdraw::Text labelText(const debugdraw::Label& label, const Eigen::Vector2d& anchor);

// The pixel rectangle a text covers, outline included: x0, y0, x1, y1.
std::array<float, 4> textExtent(const debugdraw::Text& text);

// Throws std::invalid_argument for what appendText would refuse in the label's
// text (scale, length) or a non-finite position. Checked whether or not the
// label is in view, so a frame is refused the same way from every camera.
void validateLabel(const debugdraw::Label& label);

// The most vertices `triangles` may hold: maxFrameTextCharacters of the
// largest glyph (11 quads), drawn once and outlined eight times.
std::size_t maxTextVertices();

}  // namespace physdbg::render
