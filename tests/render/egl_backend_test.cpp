// The EGL backend draws what the OSMesa backend draws (both are llvmpipe
// here, so the same bytes up to rounding), and bad backend names are refused.
#include <gtest/gtest.h>

#include <cstdlib>

#include "render/renderer.h"

namespace {

namespace dd = physdbg::debugdraw;
using physdbg::render::Backend;

dd::Frame sampleFrame() {
  dd::Frame frame;
  frame.boxes.push_back({{0, 0, 0}, dd::Quat::Identity(), {1, 0.5, 0.5}, {0.9f, 0.3f, 0.2f, 1}});
  frame.spheres.push_back({{2, 0, 0}, dd::Quat::Identity(), 0.7, {0.2f, 0.8f, 0.3f, 1}});
  frame.wireBoxes.push_back({{0, 0, 0}, dd::Quat::Identity(), {1.2, 0.7, 0.7}, {1, 1, 1, 1}});
  frame.lines.push_back({{-2, -1, 0}, {3, 1, 0}, {1, 1, 0, 1}});
  frame.texts.push_back({4, 4, 2, "egl", {1, 1, 1, 1}});
  return frame;
}

TEST(EglBackend, DrawsWhatOsMesaDraws) {
  physdbg::render::Camera camera;
  camera.eye = {1, 3, 8};
  camera.target = {0.5, 0, 0};
  std::unique_ptr<physdbg::render::Renderer> egl;
  try {
    egl = std::make_unique<physdbg::render::Renderer>(physdbg::render::RendererOptions{96, 64, 0, Backend::Egl});
  } catch (const std::runtime_error& error) {
    GTEST_SKIP() << "no EGL on this machine: " << error.what();
  }
  const physdbg::render::Image fromEgl = egl->render(sampleFrame(), camera);
  physdbg::render::Renderer osmesa({96, 64, 0, Backend::OsMesa});
  const physdbg::render::Image fromOsMesa = osmesa.render(sampleFrame(), camera);
  ASSERT_EQ(fromEgl.rgba.size(), fromOsMesa.rgba.size());
  int largest = 0, drawn = 0;
  for (std::size_t i = 0; i < fromEgl.rgba.size(); ++i) {
    largest = std::max(largest, std::abs(fromEgl.rgba[i] - fromOsMesa.rgba[i]));
    drawn += fromEgl.rgba[i] != fromEgl.rgba[i % 4];  // differs from the top-left (background) pixel
  }
  EXPECT_LE(largest, 3);  // llvmpipe rounding, see shared notes
  EXPECT_GT(drawn, 500);  // the frame is not blank
}

TEST(EglBackend, UnknownBackendNamesAreRefused) {
  EXPECT_EQ(physdbg::render::parseBackend("egl"), Backend::Egl);
  EXPECT_EQ(physdbg::render::parseBackend("osmesa"), Backend::OsMesa);
  EXPECT_THROW(physdbg::render::parseBackend("vulkan"), std::invalid_argument);
  EXPECT_THROW(physdbg::render::parseBackend(""), std::invalid_argument);
}

}  // namespace
