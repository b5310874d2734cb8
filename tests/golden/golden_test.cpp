// Golden-image tests: each case's rendered frame against its approved PNG for
// this renderer (skipped with a message when the renderer has no goldens),
// repeatability, and proof that the comparison catches real regressions.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "golden/frame_check.h"
#include "golden/golden_store.h"
#include "golden/report_folder.h"
#include "render/image_compare.h"
#include "tests/golden/golden_cases.h"
#include "viewer/frame_renderer.h"

namespace physdbg::golden {

// Test names show the case name instead of the bytes of the struct.
void PrintTo(const GoldenCase& golden, std::ostream* out) { *out << golden.name; }

namespace {

namespace fs = std::filesystem;

render::Renderer& sharedRenderer() {
  static render::Renderer renderer({kWidth, kHeight, 0});
  return renderer;
}

render::Image renderCase(const GoldenCase& golden, render::Renderer& renderer = sharedRenderer()) {
  return renderGoldenCase(golden, renderer);
}

std::string fileBytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(GoldenKey, NamesMesaVersionAndRenderer) {
  EXPECT_EQ(goldenKey({"llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6"}),
            "mesa-22.3.6-llvmpipe");
  EXPECT_EQ(goldenKey({"softpipe", "3.3 (Core Profile) Mesa 25.0.1-devel"}), "mesa-25.0.1-devel-softpipe");
  EXPECT_EQ(goldenKey({"Some GPU/PCIe", "4.6.0 NVIDIA 535.1"}), "4.6.0-nvidia-535.1-some");
  EXPECT_THROW(goldenKey({"", "4.5"}), std::invalid_argument);
}

TEST(GoldenCases, CoverEveryDebugLayer) {
  debugdraw::LayerSet covered;
  for (const GoldenCase& golden : goldenCases()) {
    if (!golden.layers.empty()) covered.bits |= debugdraw::parseLayers(golden.layers).bits;  // "": the tree view
  }
  for (const auto& [name, layer] : debugdraw::allLayers()) EXPECT_TRUE(covered.has(layer)) << name;
  EXPECT_THROW(goldenCase("no_such_case"), std::invalid_argument);
}

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(GoldenImage, MatchesApprovedImage) {
  const GoldenCase& golden = GetParam();
  const std::string key = goldenKey(sharedRenderer().glIdentity());
  if (!fs::is_directory(fs::path(PHYSDBG_GOLDEN_DIR) / key))
    GTEST_SKIP() << "no goldens for renderer key '" << key << "' (GL_RENDERER '" << sharedRenderer().glIdentity().renderer
                 << "'): tests/golden/" << key << "/ does not exist. Create it with bash scripts/update-goldens.sh";
  const fs::path expectedPath = goldenPath(PHYSDBG_GOLDEN_DIR, key, golden.name);
  ASSERT_TRUE(fs::exists(expectedPath)) << expectedPath << " is missing; run bash scripts/update-goldens.sh";
  const render::Image expected = render::readPng(expectedPath.string());
  const render::Image actual = renderCase(golden);
  const fs::path report = PHYSDBG_GOLDEN_REPORT_DIR;
  const std::string drawn = golden.layers + " after " + std::to_string(golden.steps) + " steps";
  const FrameResult frame = checkFrame({drawn, &expected, &actual}, report, golden.name);
  const ReportPage page{"physdbg golden tests: failures",
                        "If the change is intended: bash scripts/update-goldens.sh, then review the new PNGs.", true};
  if (frame.verdict == Verdict::Passed) {
    clearCase(report, page, golden.name);
    return;
  }
  const fs::path folder = recordCase(report, page, {golden.name, drawn, frame.verdict, "", {frame}, 0});
  ADD_FAILURE() << golden.name << " (" << drawn << "): " << frame.figures
                << "\n  expected, actual and diff images: " << folder.string()
                << "\n  report: " << reportIndex(report).string()
                << "\n  if the change is intended: bash scripts/update-goldens.sh";
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenImage, ::testing::ValuesIn(goldenCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) { return info.param.name; });

// Same scene and options give the same PNG bytes, also from a fresh context.
TEST(GoldenDeterminism, RenderingTwiceGivesIdenticalPngBytes) {
  const fs::path folder = fs::temp_directory_path() / ("physdbg-golden-determinism-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  render::Renderer second({kWidth, kHeight, 0});
  for (const GoldenCase& golden : goldenCases()) {
    render::writePng((folder / "first.png").string(), renderCase(golden), 9);
    render::writePng((folder / "second.png").string(), renderCase(golden, second), 9);
    EXPECT_EQ(fileBytes(folder / "first.png"), fileBytes(folder / "second.png")) << golden.name;
  }
  fs::remove_all(folder);
}

// The regression proofs start from the case with shapes, AABBs and contacts.
class GoldenRegression : public ::testing::Test {
 protected:
  const GoldenCase& golden = goldenCase("stack_aabbs_contacts");
  const SceneDescription scene = golden.scene();
  const render::Camera camera = viewer::sceneCamera(scene, double(kWidth) / kHeight);
  const World world = viewer::simulateScene(scene, golden.steps);
  const render::Image reference = renderCase(golden);

  render::Image draw(const World& drawn, const std::string& layers) {
    return sharedRenderer().render(viewer::sceneFrame(scene, drawn, debugdraw::parseLayers(layers)), camera);
  }

  // World length of `pixels` pixels at the camera target's distance.
  double worldLength(double pixels) const {
    const double distance = (camera.eye - camera.target).norm();
    return pixels * 2 * distance * std::tan(camera.fovYDegrees * M_PI / 360) / kHeight;
  }
};

// Fails, and not by a hair: at least three times the pixels the defaults allow
// (dropping the contacts layer of this frame removes about 75 pixels, 5 times).
void expectClearFailure(const render::CompareResult& result) {
  EXPECT_FALSE(result.passed) << render::describeComparison(result);
  EXPECT_GE(result.differentShare(), 3 * render::CompareOptions{}.maxDifferentShare)
      << render::describeComparison(result);
}

TEST_F(GoldenRegression, UnchangedSceneRenderedAgainPasses) {
  const render::CompareResult result = render::compareImages(reference, draw(world, golden.layers));
  EXPECT_TRUE(result.passed);
  EXPECT_TRUE(result.identical);
}

TEST_F(GoldenRegression, BodyMovedByThreePixelsFails) {
  World moved = viewer::simulateScene(scene, golden.steps);
  const BodyId top = static_cast<BodyId>(moved.bodyCount() - 1);
  moved.body(top).setPosition(moved.body(top).position() + Vec3(worldLength(3), 0, 0));
  const render::CompareResult result = render::compareImages(reference, draw(moved, golden.layers));
  expectClearFailure(result);
}

TEST_F(GoldenRegression, DroppedContactsLayerFails) {
  const render::CompareResult result = render::compareImages(reference, draw(world, "shapes,aabbs"));
  expectClearFailure(result);
}

TEST_F(GoldenRegression, ChangedBoxColourFails) {
  debugdraw::Frame frame = viewer::sceneFrame(scene, world, debugdraw::parseLayers(golden.layers));
  ASSERT_GE(frame.boxes.size(), 2u);
  debugdraw::Color& colour = frame.boxes.back().color;
  colour.r = colour.r > 0.5f ? colour.r - 0.15f : colour.r + 0.15f;
  const render::CompareResult result = render::compareImages(reference, sharedRenderer().render(frame, camera));
  expectClearFailure(result);
}

}  // namespace
}  // namespace physdbg::golden
