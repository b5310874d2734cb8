#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "render/frame_batches.h"
#include "render/gl_context.h"
#include "render/gpu_mesh.h"
#include "render/mesh_cache.h"
#include "render/outline_layer.h"
#include "render/render_target.h"
#include "render/shaders.h"
#include "render/sphere_detail.h"
#include "render/vertex_stream.h"

namespace physdbg::render {
namespace {

using Eigen::Vector3d;
using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double>(end - start).count();
}

constexpr int kMaxDimension = 16384;
constexpr int kMaxSamples = 16;
constexpr float kBackground[4] = {0.11f, 0.12f, 0.14f, 1.0f};
// A pixel left, right, up and down: a one-pixel outline round lines and cones.
constexpr float kOutlineShifts[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
// The outline's pixel, a line's half width and its ends' rounding, with room
// for float against double projections.
constexpr double kFootprintMargin = 3;

void validate(const RendererOptions& options) {
  if (options.width <= 0 || options.height <= 0 || options.width > kMaxDimension || options.height > kMaxDimension)
    throw std::invalid_argument("Renderer: width and height must be in 1.." + std::to_string(kMaxDimension) +
                                ", got " + std::to_string(options.width) + "x" + std::to_string(options.height));
  if (options.samples < 0 || options.samples > kMaxSamples)
    throw std::invalid_argument("Renderer: samples must be in 0.." + std::to_string(kMaxSamples));
}

// Light from above and behind the camera, a little to the right, so the three
// faces of a box seen from a 3/4 view get clearly different brightness.
Eigen::Vector3f lightDirection(const Camera& camera) {
  const Vector3d back = (camera.eye - camera.target).normalized();
  const Vector3d right = (-back).cross(camera.up).normalized();
  return (0.5 * back + camera.up.normalized() + 0.3 * right).normalized().cast<float>();
}

struct DepthRange {
  double nearDistance, farDistance;
};

// Near and far planes that enclose the frame's bounds with a small margin; a
// near plane no closer than 1e-4 of the far one keeps 24-bit depth useful.
DepthRange depthRange(const debugdraw::Frame& frame, const Camera& camera) {
  const Bounds bounds = frameBounds(frame);
  const Vector3d eye = camera.eye - camera.target;
  const double distance = eye.norm();
  if (bounds.empty()) return camera.orthographic ? DepthRange{0, 2 * distance} : DepthRange{distance * 1e-2, distance * 1e2};
  const Vector3d forward = -eye / distance;
  double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
  for (int corner = 0; corner < 8; ++corner) {
    const Vector3d point((corner & 1 ? bounds.max : bounds.min).x(), (corner & 2 ? bounds.max : bounds.min).y(),
                         (corner & 4 ? bounds.max : bounds.min).z());
    const double depth = (point - camera.target - eye).dot(forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  // Arrow heads reach up to 0.08 of their arrow's length off the bounds, and a
  // flat scene must still get a depth range of some thickness.
  const double margin = 0.1 * (bounds.max - bounds.min).norm() + 1e-6 * distance + 1e-9;
  farthest += margin;
  nearest -= margin;
  if (camera.orthographic) return {nearest, farthest};
  if (farthest <= 0) return {distance * 1e-2, distance};  // everything behind the camera
  return {std::max(nearest, farthest * 1e-4), farthest};
}

// Alpha stays 1 over the opaque background so PNGs are opaque.
void blendOver() { glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA); }

// Markers outlined by dark copies drawn first, as asked or with MSAA: the
// arrows' outline layer needs single-sample coverage, and a pixel a point
// covers only in part must keep its share of the ring under it.
bool outlinesByCopies(const RendererOptions& options) { return options.samples > 0 || options.outlineMarkersByCopies; }

}  // namespace

class Renderer::Impl {
 public:
  explicit Impl(const RendererOptions& options)
      : options_(options),
        context_(options.backend == Backend::Egl ? createEglContext() : createOsMesaContext()),
        solid_(createProgram(shaders::kSolidVertex, shaders::kSolidFragment, "solid")),
        flatSolid_(createProgram(shaders::kFlatSolidVertex, shaders::kFlatSolidFragment, "flat solid")),
        wire_(createProgram(shaders::kWireVertex, shaders::kUnlitFragment, "wire")),
        line_(createProgram(shaders::kLineVertex, shaders::kUnlitFragment, "line")),
        point_(createProgram(shaders::kPointVertex, shaders::kPointFragment, "point")),
        text_(createProgram(shaders::kTextVertex, shaders::kUnlitFragment, "text")),
        cube_(uploadInstancedMesh(unitCube(), GL_TRIANGLES)),
        spheres_(uploadSphereLevels()),
        coarseCone_(uploadInstancedMesh(unitCone(kCoarseConeSegments), GL_TRIANGLES)),
        fineCone_(uploadInstancedMesh(unitCone(kFineConeSegments), GL_TRIANGLES)),
        cubeEdges_(uploadInstancedMesh(unitCubeEdges(), GL_LINES)),
        lines_(sizeof(ColoredVertex),
               {{0, 3, offsetof(ColoredVertex, position)}, {1, 4, offsetof(ColoredVertex, color)}}),
        points_(sizeof(PointVertex), {{0, 3, offsetof(PointVertex, position)},
                                      {1, 1, offsetof(PointVertex, size)},
                                      {2, 4, offsetof(PointVertex, color)}}),
        texts_(sizeof(TextVertex), {{0, 2, offsetof(TextVertex, position)}, {1, 4, offsetof(TextVertex, color)}}),
        target_(options.width, options.height, options.samples) {}

  // GL objects must die while their context is current.
  ~Impl() { context_->makeCurrent(); }

  Image render(const debugdraw::Frame& frame, const Camera& camera) {
    const auto start = Clock::now();
    validateCamera(camera);
    const Eigen::Matrix4f viewProjection = viewProjectionMatrix(frame, camera);
    const ScreenMapping screen{viewProjection.cast<double>(), static_cast<double>(options_.width),
                               static_cast<double>(options_.height)};
    const FrameBatches batches = buildFrameBatches(frame, camera.target, &screen);
    const auto drawStart = Clock::now();
    timings_.prepareSeconds = secondsBetween(start, drawStart);
    context_->makeCurrent();
    target_.bindForDrawing();
    setUpState();
    drawSolids(batches, camera, viewProjection);
    drawOverlays(batches, viewProjection);
    drawMarkers(batches, camera, viewProjection);
    drawText(batches);
    meshCache_.endFrame();
    glFinish();  // llvmpipe rasterises here, so read-back is timed apart
    checkGlError("rendering a frame");
    const auto readStart = Clock::now();
    timings_.drawSeconds = secondsBetween(drawStart, readStart);
    Image image = target_.read();
    timings_.readBackSeconds = secondsBetween(readStart, Clock::now());
    return image;
  }

  const RenderTimings& lastTimings() const { return timings_; }

  const RendererOptions& options() const { return options_; }

  GlIdentity glIdentity() {
    context_->makeCurrent();
    auto text = [](GLenum name) {
      const GLubyte* value = glGetString(name);
      return value ? std::string(reinterpret_cast<const char*>(value)) : std::string("?");
    };
    return {text(GL_RENDERER), text(GL_VERSION)};
  }

 private:
  void setUpState() {
    glClearColor(kBackground[0], kBackground[1], kBackground[2], kBackground[3]);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    blendOver();
    glEnable(GL_PROGRAM_POINT_SIZE);
    // Flat normals (the cone's) come from a triangle's first vertex.
    glProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
  }

  Eigen::Matrix4f viewProjectionMatrix(const debugdraw::Frame& frame, const Camera& camera) const {
    const DepthRange range = depthRange(frame, camera);
    const double aspect = static_cast<double>(options_.width) / options_.height;
    return (projectionMatrix(camera, aspect, range.nearDistance, range.farDistance) * relativeViewMatrix(camera))
        .cast<float>();
  }

  // Also clears the marker outline uniforms, which the programs share with markers.
  void useProgram(const GlProgram& program, const Eigen::Matrix4f& viewProjection) {
    glUseProgram(program.get());
    glUniformMatrix4fv(glGetUniformLocation(program.get(), "uViewProjection"), 1, GL_FALSE, viewProjection.data());
    setOutline(program, 0, 0, false);
  }

  // Shifts the program's geometry by (x, y) pixels, in the outline colour or not.
  void setOutline(const GlProgram& program, float x, float y, bool outline) const {
    glUniform2f(glGetUniformLocation(program.get(), "uShift"), 2.0f * x / static_cast<float>(options_.width),
                2.0f * y / static_cast<float>(options_.height));
    glUniform1f(glGetUniformLocation(program.get(), "uOutline"), outline ? 1.0f : 0.0f);
  }

  static std::vector<InstancedMesh> uploadSphereLevels() {
    std::vector<InstancedMesh> levels;
    for (int segments : kSphereSegments) levels.push_back(uploadInstancedMesh(capsuleSphere(segments, segments / 2), GL_TRIANGLES));
    return levels;
  }

  // One instanced draw per detail level in use.
  void drawRound(const std::vector<Instance>& instances, const Camera& camera) {
    const auto levels = splitByDetail(instances, camera, options_.height);
    for (std::size_t level = 0; level < levels.size(); ++level) drawInstances(spheres_[level], levels[level]);
  }

  // Translucent solids (sensors) go after the opaque ones, without writing
  // depth: drawn first, a see-through box would hide what is inside it.
  void drawSolids(const FrameBatches& batches, const Camera& camera, const Eigen::Matrix4f& viewProjection) {
    const Eigen::Vector3f light = lightDirection(camera);
    // Pushed back slightly so wire boxes and lines on their surfaces stay visible.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    useProgram(solid_, viewProjection);
    glUniform3fv(glGetUniformLocation(solid_.get(), "uLightDirection"), 1, light.data());
    drawSolidPass(batches, camera, false);
    if (hasTranslucentSolids(batches)) {
      glDepthMask(GL_FALSE);
      drawSolidPass(batches, camera, true);
      glDepthMask(GL_TRUE);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  static bool translucent(const Instance& instance) { return instance.color[3] < 1.0f; }

  static bool hasTranslucentSolids(const FrameBatches& batches) {
    const auto any = [](const std::vector<Instance>& instances) {
      return std::any_of(instances.begin(), instances.end(), translucent);
    };
    if (any(batches.boxes) || any(batches.spheres) || any(batches.capsules)) return true;
    return std::any_of(batches.meshes.begin(), batches.meshes.end(),
                       [&](const MeshBatch& batch) { return any(batch.instances); });
  }

  static std::vector<Instance> select(const std::vector<Instance>& instances, bool wantTranslucent) {
    std::vector<Instance> chosen;
    for (const Instance& instance : instances)
      if (translucent(instance) == wantTranslucent) chosen.push_back(instance);
    return chosen;
  }

  void drawSolidPass(const FrameBatches& batches, const Camera& camera, bool wantTranslucent) {
    // Boxes, spheres and capsules are closed and counter-clockwise from
    // outside (flat boxes keep both faces), so back faces never show:
    // skipping them halves the fill. Meshes are not culled: level geometry
    // (triangle meshes, heightfields) is an open surface, touched from either side.
    glEnable(GL_CULL_FACE);
    drawInstances(cube_, select(batches.boxes, wantTranslucent));
    drawRound(select(batches.spheres, wantTranslucent), camera);
    drawRound(select(batches.capsules, wantTranslucent), camera);
    glDisable(GL_CULL_FACE);
    for (const MeshBatch& batch : batches.meshes)
      drawInstances(meshCache_.get(*batch.mesh), select(batch.instances, wantTranslucent));
  }

  void drawOverlays(const FrameBatches& batches, const Eigen::Matrix4f& viewProjection) {
    useProgram(wire_, viewProjection);
    drawInstances(cubeEdges_, batches.wireBoxes);
    useProgram(line_, viewProjection);
    lines_.draw(batches.lines, GL_LINES);
  }

  // Contact points, contact normals and velocities are what a debug picture is
  // for, and they start inside or on the bodies: they are drawn over
  // everything (no depth test; depth clamping keeps the ones past the near or
  // far plane), each with a one-pixel dark outline so they read on any body
  // colour. Points first, so the arrows leaving them stay whole.
  void drawMarkers(const FrameBatches& batches, const Camera& camera, const Eigen::Matrix4f& viewProjection) {
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_DEPTH_CLAMP);
    drawPoints(batches, viewProjection);
    drawArrows(batches, camera, viewProjection);
    glDisable(GL_DEPTH_CLAMP);
    glEnable(GL_DEPTH_TEST);
  }

  void drawPoints(const FrameBatches& batches, const Eigen::Matrix4f& viewProjection) {
    if (batches.points.empty()) return;
    useProgram(point_, viewProjection);
    const GLint grow = glGetUniformLocation(point_.get(), "uGrowPixels");
    const GLint ring = glGetUniformLocation(point_.get(), "uRing");
    glUniform1f(grow, 2.0f);  // a one-pixel ring
    points_.upload(batches.points);
    if (outlinesByCopies(options_)) {
      glUniform1f(ring, 0.0f);
      setOutline(point_, 0, 0, true);
      points_.drawUploaded(GL_POINTS);
      glUniform1f(grow, 0.0f);
      setOutline(point_, 0, 0, false);
      points_.drawUploaded(GL_POINTS);
      return;
    }
    // Nothing after the markers tests depth, so the solids' depth can go.
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUniform1f(ring, 1.0f);
    points_.drawUploaded(GL_POINTS);
    glDisable(GL_DEPTH_TEST);
  }

  // Arrow heads are lit cones, culled to their front faces so a cone never
  // draws over itself; small ones coarser, drawn before the others. Shafts
  // and heads are uploaded once for every pass.
  void drawArrows(const FrameBatches& batches, const Camera& camera, const Eigen::Matrix4f& viewProjection) {
    if (batches.arrowShafts.empty()) return;
    lines_.upload(batches.arrowShafts);
    const ConesByDetail heads = splitConesByDetail(batches.arrowHeads, camera, options_.height);
    uploadInstances(coarseCone_, heads.coarse);
    uploadInstances(fineCone_, heads.fine);
    const Eigen::Vector3f light = lightDirection(camera);
    useProgram(flatSolid_, viewProjection);
    glUniform3fv(glGetUniformLocation(flatSolid_.get(), "uLightDirection"), 1, light.data());
    glEnable(GL_CULL_FACE);
    if (!outlinesByCopies(options_)) {
      // Made with the first arrows: a renderer that never draws one (a large
      // image of solids) does not hold a second image's worth of memory.
      if (!outlineLayer_) outlineLayer_.emplace(options_.width, options_.height);
      outlineLayer_->begin();
      drawUploadedArrows(viewProjection, 0, 0, false);
      glDisable(GL_CULL_FACE);
      outlineLayer_->compositeOnto(
          target_, arrowFootprint(batches, viewProjection, options_.width, options_.height, kFootprintMargin));
      blendOver();
      return;
    }
    for (const auto& shift : kOutlineShifts) drawUploadedArrows(viewProjection, shift[0], shift[1], true);
    drawUploadedArrows(viewProjection, 0, 0, false);
    glDisable(GL_CULL_FACE);
  }

  void drawUploadedArrows(const Eigen::Matrix4f& viewProjection, float x, float y, bool outline) {
    useProgram(line_, viewProjection);
    setOutline(line_, x, y, outline);
    lines_.drawUploaded(GL_LINES);
    useProgram(flatSolid_, viewProjection);
    setOutline(flatSolid_, x, y, outline);
    drawUploadedInstances(coarseCone_);
    drawUploadedInstances(fineCone_);
  }

  void drawText(const FrameBatches& batches) {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(text_.get());
    glUniform2f(glGetUniformLocation(text_.get(), "uViewportSize"), static_cast<float>(options_.width),
                static_cast<float>(options_.height));
    texts_.draw(batches.texts, GL_TRIANGLES);
  }

  RendererOptions options_;
  std::unique_ptr<GlContext> context_;  // declared first: destroyed after every GL object
  GlProgram solid_, flatSolid_, wire_, line_, point_, text_;
  InstancedMesh cube_;
  std::vector<InstancedMesh> spheres_;  // one per detail level
  InstancedMesh coarseCone_, fineCone_, cubeEdges_;
  VertexStream lines_, points_, texts_;
  MeshCache meshCache_;
  RenderTarget target_;
  std::optional<OutlineLayer> outlineLayer_;
  RenderTimings timings_;
};

Backend parseBackend(const std::string& name) {
  if (name == "osmesa") return Backend::OsMesa;
  if (name == "egl") return Backend::Egl;
  throw std::invalid_argument("unknown GL backend '" + name + "' (choose osmesa or egl)");
}

Renderer::Renderer(const RendererOptions& options) {
  validate(options);
  impl_ = std::make_unique<Impl>(options);
}

Renderer::~Renderer() = default;

Image Renderer::render(const debugdraw::Frame& frame, const Camera& camera) { return impl_->render(frame, camera); }

const RendererOptions& Renderer::options() const { return impl_->options(); }

const RenderTimings& Renderer::lastTimings() const { return impl_->lastTimings(); }

GlIdentity Renderer::glIdentity() const { return impl_->glIdentity(); }

}  // namespace physdbg::render
