#pragma once
// GLSL 3.30 sources. Positions arrive relative to the camera target.
namespace physdbg::render::shaders {

// Instanced solids: rotation quaternion, scale, capsule stretch; Lambert + ambient.
// Solids, lines and points take uShift/uOutline to draw a marker's dark outline.
extern const char* const kSolidVertex;
extern const char* const kSolidFragment;
// The same with a `flat` normal, taken from a face's first vertex (the cone).
extern const char* const kFlatSolidVertex;
extern const char* const kFlatSolidFragment;
// Instanced wire boxes: the same instance layout, no lighting.
extern const char* const kWireVertex;
// Per-vertex coloured lines.
extern const char* const kLineVertex;
extern const char* const kUnlitFragment;
// Round points of a given pixel size.
extern const char* const kPointVertex;
extern const char* const kPointFragment;
// Screen-space text in pixels from the top-left corner.
extern const char* const kTextVertex;

}  // namespace physdbg::render::shaders
