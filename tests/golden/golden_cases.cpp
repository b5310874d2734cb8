#include "tests/golden/golden_cases.h"

#include <stdexcept>

#include "scenes/stacking_scenes.h"
#include "viewer/frame_renderer.h"
#include "viewer/tree_view.h"

namespace physdbg::golden {
namespace {

std::function<SceneDescription()> builtin(const std::string& name) {
  return [name] { return resolveScene(name); };
}

// balls24 as the goldens were approved: with the sequential-impulse solver,
// which the design's scenes used before they took the design's response
// (issue 16). The layers shown do not depend on the solver; the positions do.
std::function<SceneDescription()> balls24SequentialImpulse() {
  return [] {
    SceneDescription scene = resolveScene("balls24");
    scene.world.solver.kind = SolverKind::SequentialImpulse;
    return scene;
  };
}

// A closer 3/4 view than the default framing, which fits the whole floor slab.
std::function<SceneDescription()> closeUp(SceneDescription (*make)(int), int size, const Vec3& target,
                                          double distance) {
  return [=] {
    SceneDescription scene = make(size);
    scene.camera = SceneCamera{target + distance * Vec3(0.6, 0.45, 1.0).normalized(), target};
    return scene;
  };
}

SceneDescription pyramid(int base) { return pyramidScene(base); }

// A shipped scene file, seen from `eye` toward `target`.
std::function<SceneDescription()> sceneFile(const std::string& name, const Vec3& eye, const Vec3& target) {
  return [=] {
    SceneDescription scene = loadSceneFile(std::string(PHYSDBG_SOURCE_DIR) + "/scenes/" + name);
    scene.camera = SceneCamera{eye, target};
    return scene;
  };
}

// A frame through the whole `physdbg render` path (SceneFrames, the viewer's
// selection), for what only that path draws: focus, labels, the grid.
std::function<render::Image(render::Renderer&)> viewed(std::function<SceneDescription()> scene, int frame,
                                                       const std::string& layers, std::vector<int> highlight = {},
                                                       bool labels = false) {
  return [=](render::Renderer& renderer) {
    viewer::ViewOptions options;
    options.layers = debugdraw::parseLayers(layers);
    options.highlight = highlight;
    options.labels = labels;
    return viewer::renderViewFrame(renderer, scene(), frame, options);
  };
}

}  // namespace

const std::vector<GoldenCase>& goldenCases() {
  static const std::vector<GoldenCase> cases = {
      // Solid and wire shapes of every common collider, and the overlay text.
      {"default_shapes_wire_overlay", builtin("default"), 45, "shapes,wire,overlay", {}},
      // Resting contacts: red AABBs of touching bodies, contact points and normals.
      // 20 steps: still awake (sleeping bodies keep no contacts to draw).
      {"stack_aabbs_contacts", closeUp(stackScene, 4, Vec3(0, 2, 0), 9.0), 20, "shapes,aabbs,contacts", {}},
      // The broad phase: fat boxes and the tree's internal nodes.
      {"balls24_fat_tree", balls24SequentialImpulse(), 40, "wire,fat,tree", {}},
      // Moving bodies: velocity arrows and candidate pairs (wire, so solids hide neither).
      {"balls24_velocities_pairs", balls24SequentialImpulse(), 40, "wire,velocities,pairs", {}},
      // Sleeping bodies (darker) once a small pyramid has settled.
      {"pyramid_sleep", closeUp(pyramid, 4, Vec3(0, 1.8, 0), 8.5), 90, "shapes,sleep,aabbs", {}},
      // The tree-rotation view: the first insertion of a small pyramid's boxes
      // that rotates the tree, after the swap (highlighted subtrees, diagram).
      {"tree_rotation_pyramid", [] { return pyramidScene(4); }, 0, "",
       [](render::Renderer& renderer) { return viewer::renderTreeRotationFrame(pyramidScene(4), 0, true, renderer); }},
      // One body in focus: body 5 of a small pyramid emphasised with its
      // contacts, pairs and tree path (gold), the rest faded, every body labelled.
      {"pyramid_highlight_labels", closeUp(pyramid, 4, Vec3(0, 1.8, 0), 8.5), 30, "shapes,overlay",
       viewed(closeUp(pyramid, 4, Vec3(0, 1.8, 0), 8.5), 30, "shapes,overlay", {5}, true)},
      // Contact forces of a resting stack (arrows on one scale, legend) over
      // the ground grid with its metre labels and axis gizmo.
      {"stack_impulses_grid", closeUp(stackScene, 4, Vec3(0, 2, 0), 9.0), 20, "shapes,impulses,grid",
       viewed(closeUp(stackScene, 4, Vec3(0, 2, 0), 9.0), 20, "shapes,impulses,grid")},
      // Level geometry: a box sliding across a floor of triangles, the
      // triangles it was tested against (orange) and the seams whose normals
      // were corrected (magenta), over the mesh's wire triangles.
      {"mesh_level_mesh", sceneFile("mesh_level.json", Vec3(-3.0, 3.5, 8.0), Vec3(-5.6, 0.3, 3.6)), 40,
       "shapes,wire,contacts,mesh", {}},
  };
  return cases;
}

render::Image renderGoldenCase(const GoldenCase& golden, render::Renderer& renderer) {
  if (golden.draw) return golden.draw(renderer);
  return viewer::renderSceneFrame(renderer, golden.scene(), golden.steps, debugdraw::parseLayers(golden.layers));
}

const GoldenCase& goldenCase(const std::string& name) {
  for (const GoldenCase& candidate : goldenCases())
    if (candidate.name == name) return candidate;
  throw std::invalid_argument("no golden case named '" + name + "'");
}

}  // namespace physdbg::golden
