#pragma once
#include "render/renderer.h"
// The scenes, step counts and debug layers of the golden images. Together the
// cases cover every debug layer; the golden PNG of case NAME is
// tests/golden/KEY/NAME.png (KEY: see golden_store.h).
#include <functional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace physdbg::golden {

// Small frames keep goldens a few KB and the tests fast.
inline constexpr int kWidth = 320, kHeight = 240;

struct GoldenCase {
  std::string name;
  std::function<SceneDescription()> scene;
  int steps = 0;
  std::string layers;
  // Set for pictures drawn another way: the tree-rotation view, or a frame
  // through the whole render path (focus, labels, grid).
  std::function<render::Image(render::Renderer&)> draw;
};

// The case's picture: `draw` when set, else the scene after `steps` steps with `layers`.
render::Image renderGoldenCase(const GoldenCase& golden, render::Renderer& renderer);

const std::vector<GoldenCase>& goldenCases();
// Throws std::invalid_argument naming the unknown case.
const GoldenCase& goldenCase(const std::string& name);

}  // namespace physdbg::golden
