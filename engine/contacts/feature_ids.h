#pragma once
// How a manifold point's feature id is made, shared by every manifold
// builder so that a box pair gives the same ids whichever builder ran.
// The solver matches a point to last step's by (pair, feature id) alone to
// warm-start it, so an id must name the same geometric point from one step
// to the next: it is built from which shape holds the reference face, that
// face, the incident feature, and the incident vertex or clipped edge the
// point came from, never from positions.
#include <cstdint>

namespace physdbg {

// Bit 31: B holds the reference face; bits 21-30: reference face; bits
// 12-20: incident feature; bits 0-11: the point's tag.
inline std::uint32_t featureBase(bool referenceIsA, int referenceIndex, int incidentIndex) {
  return (referenceIsA ? 0u : 1u << 31) | (std::uint32_t(referenceIndex & 0x3FF) << 21) |
         (std::uint32_t(incidentIndex & 0x1FF) << 12);
}

// The general builder's tag of a point where the polygon edge from the point
// tagged `a` to the one tagged `b` crosses side plane `plane`. Incident
// vertices are tagged 1, 2, ...; crossing tags have bit 11 set so they never
// equal a vertex's. A hash of the clipping history: it can collide (the box
// builder names clipped points by their lines instead, box_face.h).
inline std::uint32_t mixTags(std::uint32_t a, std::uint32_t b, std::uint32_t plane) {
  return (0x800u | ((a * 31u + b) * 7u + plane)) & 0xFFFu;
}

}  // namespace physdbg
