#pragma once
// The debugger's view of a world: its state turned into debug-draw
// primitives, one function per layer, only the requested layers computed.
// It reads the world through its public API (bodies and their flags, the
// broad phase's boxes and tree, the contacts the world shows); the world
// itself knows no layers, colours or legends.
#include "debugdraw/primitives.h"

namespace physdbg {

class World;

// Appends the primitives of the requested layers; computes nothing for the
// layers that are not requested. With `counts`, adds how many primitives
// each layer appended, so a caller can say which layer drew nothing.
// Every primitive is tagged (debugdraw::Tag): its layer, its body or the
// pair it belongs to, and tree nodes, so a viewer can filter after the run.
void emitDebugDraw(const World& world, debugdraw::LayerSet layers, debugdraw::Frame& frame,
                   debugdraw::LayerCounts* counts = nullptr);
// Appends one BodyInfo per body, in body order, so a viewer can label,
// follow and highlight bodies without the engine. Names stay empty: the
// scene knows them, the world does not.
void emitBodies(const World& world, debugdraw::Frame& frame);
// Metres per newton of the impulses layer's force arrows: the heaviest
// dynamic body's weight about as long as its size, on a 1-2-5 series.
// Depends on masses and shapes only, so it holds for the whole run.
double impulseScale(const World& world);

}  // namespace physdbg
