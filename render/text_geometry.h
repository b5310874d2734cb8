#pragma once
// Screen-space text from stb_easy_font: each glyph is a set of axis-aligned
// quads on a one-unit grid; scaled and rounded to whole pixels they stay crisp.
#include <vector>

#include "debugdraw/primitives.h"
#include "render/frame_batches.h"

namespace physdbg::render {

// Glyph quads as two triangles each, in the text's colour. Throws
// std::invalid_argument for a non-positive or non-finite scale or position.
void appendText(const debugdraw::Text& text, std::vector<TextVertex>& triangles);

// A dark outline (the glyphs offset one step in eight directions) so text reads
// on light and dark backgrounds alike. Draw it before the glyphs.
void appendTextOutline(const debugdraw::Text& text, std::vector<TextVertex>& triangles);

}  // namespace physdbg::render
