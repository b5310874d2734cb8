#include "render/shaders.h"

namespace physdbg::render::shaders {

#define PHYSDBG_INSTANCE_INPUTS                  \
  "layout(location = 2) in vec3 iTranslation;\n" \
  "layout(location = 3) in vec4 iRotation;\n"    \
  "layout(location = 4) in vec4 iScale;\n"       \
  "layout(location = 5) in vec4 iColor;\n"       \
  "vec3 rotate(vec4 q, vec3 v) {\n"              \
  "  vec3 t = 2.0 * cross(q.xyz, v);\n"          \
  "  return v + q.w * t + cross(q.xyz, t);\n"    \
  "}\n"

// Markers' dark outline colour (render/outline_layer.cpp lays the bytes
// llvmpipe's blending made of it, 10, 10, 12).
#define PHYSDBG_OUTLINE_RGB "vec3(0.04, 0.04, 0.05)"

// Markers (arrows, points) are drawn first in a dark outline colour shifted
// by a pixel in each direction, then in their own colour. Both uniforms are
// zero for every other draw.
#define PHYSDBG_OUTLINE_INPUTS                                            \
  "uniform vec2 uShift;\n"    /* clip-space offset of one outline copy */ \
  "uniform float uOutline;\n" /* 1: draw in the outline colour */         \
  "vec4 outlined(vec4 color) {\n"                                         \
  "  return mix(color, vec4(" PHYSDBG_OUTLINE_RGB                         \
  ", color.a), uOutline);\n"                                              \
  "}\n"                                                                   \
  "vec4 shifted(vec4 position) {\n"                                       \
  "  return vec4(position.xy + uShift * position.w, position.zw);\n"      \
  "}\n"

// The solid program, its normal smooth (spheres, capsules) or `flat` (the
// shared-vertex cone): the same text otherwise, so both compute alike.
#define PHYSDBG_SOLID_VERTEX(NORMAL_QUALIFIER)                                                             \
  "#version 330 core\n"                                                                                    \
  "layout(location = 0) in vec4 aPosition;\n"                                                              \
  "layout(location = 1) in vec3 aNormal;\n" PHYSDBG_INSTANCE_INPUTS                                        \
  "uniform mat4 uViewProjection;\n" PHYSDBG_OUTLINE_INPUTS NORMAL_QUALIFIER "out vec3 vNormal;\n"           \
  "out vec4 vColor;\n"                                                                                     \
  "void main() {\n"                                                                                        \
  "  vec3 local = aPosition.xyz * iScale.xyz + vec3(0.0, aPosition.w * iScale.w, 0.0);\n"                  \
  /* Inverse-transpose of a scale is its reciprocal; the floor keeps flat boxes finite. */                 \
  "  vNormal = rotate(iRotation, aNormal / max(iScale.xyz, vec3(1e-30)));\n"                               \
  "  vColor = outlined(iColor);\n"                                                                         \
  "  gl_Position = shifted(uViewProjection * vec4(rotate(iRotation, local) + iTranslation, 1.0));\n"       \
  "}\n"

#define PHYSDBG_SOLID_FRAGMENT(NORMAL_QUALIFIER)                                  \
  "#version 330 core\n" NORMAL_QUALIFIER "in vec3 vNormal;\n"                     \
  "in vec4 vColor;\n"                                                            \
  "uniform vec3 uLightDirection;\n"                                              \
  "out vec4 fragColor;\n"                                                        \
  "void main() {\n"                                                              \
  "  float lambert = max(dot(normalize(vNormal), uLightDirection), 0.0);\n"      \
  "  fragColor = vec4(vColor.rgb * (0.3 + 0.7 * lambert), vColor.a);\n"          \
  "}\n"

const char* const kSolidVertex = PHYSDBG_SOLID_VERTEX("");
const char* const kSolidFragment = PHYSDBG_SOLID_FRAGMENT("");
const char* const kFlatSolidVertex = PHYSDBG_SOLID_VERTEX("flat ");
const char* const kFlatSolidFragment = PHYSDBG_SOLID_FRAGMENT("flat ");

const char* const kWireVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec4 aPosition;\n" PHYSDBG_INSTANCE_INPUTS
    "uniform mat4 uViewProjection;\n"
    "out vec4 vColor;\n"
    "void main() {\n"
    "  vColor = iColor;\n"
    "  gl_Position = uViewProjection * vec4(rotate(iRotation, aPosition.xyz * iScale.xyz) + iTranslation, 1.0);\n"
    "}\n";

const char* const kLineVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPosition;\n"
    "layout(location = 1) in vec4 aColor;\n"
    "uniform mat4 uViewProjection;\n" PHYSDBG_OUTLINE_INPUTS
    "out vec4 vColor;\n"
    "void main() {\n"
    "  vColor = outlined(aColor);\n"
    "  gl_Position = shifted(uViewProjection * vec4(aPosition, 1.0));\n"
    "}\n";

const char* const kUnlitFragment =
    "#version 330 core\n"
    "in vec4 vColor;\n"
    "out vec4 fragColor;\n"
    "void main() { fragColor = vColor; }\n";

// A point's disc, grown by uGrowPixels for its dark ring. With uRing set one
// draw gives both: fragments within the point's own size take its colour at
// depth 0, the ring's the outline colour at depth 0.5, and with the depth
// buffer cleared and LEQUAL a ring never covers any point's inside while a
// later inside covers everything, as drawing every ring first did (for
// opaque points: a translucent point's inside no longer shows a later point's
// ring through it, and its own ring is no longer under it).
const char* const kPointVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec3 aPosition;\n"
    "layout(location = 1) in float aSize;\n"
    "layout(location = 2) in vec4 aColor;\n"
    "uniform mat4 uViewProjection;\n" PHYSDBG_OUTLINE_INPUTS
    "uniform float uGrowPixels;\n"
    "out vec4 vColor;\n"
    "out vec4 vRingColor;\n"
    "out float vInside;\n" /* squared radius of the point's own disc, in pixels */
    "void main() {\n"
    "  vColor = outlined(aColor);\n"
    "  vRingColor = vec4(" PHYSDBG_OUTLINE_RGB
    ", aColor.a);\n"
    "  vInside = 0.25 * aSize * aSize;\n"
    "  gl_PointSize = aSize + uGrowPixels;\n"
    "  gl_Position = uViewProjection * vec4(aPosition, 1.0);\n"
    // Pull towards the camera so a point on a slanted surface is not half buried.
    "  gl_Position.z -= 0.002 * gl_Position.w;\n"
    "}\n";

const char* const kPointFragment =
    "#version 330 core\n"
    "in vec4 vColor;\n"
    "in vec4 vRingColor;\n"
    "in float vInside;\n"
    "uniform float uRing;\n"
    "uniform float uGrowPixels;\n"
    "out vec4 fragColor;\n"
    "void main() {\n"
    "  vec2 offset = gl_PointCoord - vec2(0.5);\n"
    "  if (dot(offset, offset) > 0.25) discard;\n"
    "  fragColor = vColor;\n"
    "  gl_FragDepth = 0.0;\n"
    "  if (uRing == 0.0) return;\n"
    "  vec2 pixels = offset * (sqrt(4.0 * vInside) + uGrowPixels);\n"
    "  if (dot(pixels, pixels) <= vInside) return;\n"
    "  fragColor = vRingColor;\n"
    "  gl_FragDepth = 0.5;\n"
    "}\n";

const char* const kTextVertex =
    "#version 330 core\n"
    "layout(location = 0) in vec2 aPixel;\n"
    "layout(location = 1) in vec4 aColor;\n"
    "uniform vec2 uViewportSize;\n"
    "out vec4 vColor;\n"
    "void main() {\n"
    "  vColor = aColor;\n"
    "  gl_Position = vec4(2.0 * aPixel.x / uViewportSize.x - 1.0, 1.0 - 2.0 * aPixel.y / uViewportSize.y, 0.0, 1.0);\n"
    "}\n";

#undef PHYSDBG_INSTANCE_INPUTS
#undef PHYSDBG_OUTLINE_INPUTS
#undef PHYSDBG_OUTLINE_RGB
#undef PHYSDBG_SOLID_VERTEX
#undef PHYSDBG_SOLID_FRAGMENT

}  // namespace physdbg::render::shaders
