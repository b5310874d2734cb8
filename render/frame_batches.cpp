#include "render/frame_batches.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "render/text_geometry.h"

namespace physdbg::render {
namespace {

using debugdraw::Color;
using Eigen::Quaterniond;
using Eigen::Vector3d;

// Arrow heads are a fixed fraction of the arrow so they scale with the scene.
constexpr double kHeadLengthFraction = 0.2;
constexpr double kHeadRadiusFraction = 0.4;  // of the head length
constexpr double kMaximumHeadFraction = 0.5;
// An arrow seen almost end-on would need to grow without bound to span the
// minimum on screen; it grows this much at most and stays a dot.
constexpr double kMaximumArrowGrowth = 1000;

void requireFinite(const Vector3d& value, const char* what) {
  if (!value.allFinite()) throw std::invalid_argument(std::string("debug draw: ") + what + " is not finite");
}

void requireNonNegative(double value, const char* what) {
  if (!(value >= 0) || !std::isfinite(value))
    throw std::invalid_argument(std::string("debug draw: ") + what + " must be finite and >= 0");
}

Quaterniond normalizedOrientation(const Quaterniond& orientation, const char* what) {
  const double norm = orientation.norm();
  if (!(norm > 1e-12) || !std::isfinite(norm))
    throw std::invalid_argument(std::string("debug draw: ") + what + " orientation is not a rotation");
  return Quaterniond(orientation.coeffs() / norm);
}

void copy(float* target, const Vector3d& value) {
  for (int i = 0; i < 3; ++i) target[i] = static_cast<float>(value[i]);
}

void copy(float* target, const Color& color) {
  target[0] = color.r, target[1] = color.g, target[2] = color.b, target[3] = color.a;
}

Instance makeInstance(const Vector3d& relativeCenter, const Quaterniond& rotation, const Vector3d& scale,
                      double stretch, const Color& color) {
  Instance instance{};
  copy(instance.translation, relativeCenter);
  const Eigen::Vector4d q = rotation.coeffs();  // x, y, z, w
  for (int i = 0; i < 4; ++i) instance.rotation[i] = static_cast<float>(q[i]);
  copy(instance.scale, scale);
  instance.scale[3] = static_cast<float>(stretch);
  copy(instance.color, color);
  return instance;
}

template <typename Box>
Instance boxInstance(const Box& box, const Vector3d& origin, const char* what) {
  requireFinite(box.center, what);
  requireFinite(box.halfExtents, what);
  if ((box.halfExtents.array() < 0).any())
    throw std::invalid_argument(std::string("debug draw: ") + what + " half extents must be >= 0");
  return makeInstance(box.center - origin, normalizedOrientation(box.orientation, what), box.halfExtents, 0,
                      box.color);
}

void addSolids(const debugdraw::Frame& frame, const Vector3d& origin, FrameBatches& batches) {
  for (const auto& box : frame.boxes) batches.boxes.push_back(boxInstance(box, origin, "solid box"));
  for (const auto& sphere : frame.spheres) {
    requireFinite(sphere.center, "sphere centre");
    requireNonNegative(sphere.radius, "sphere radius");
    batches.spheres.push_back(makeInstance(sphere.center - origin, normalizedOrientation(sphere.orientation, "sphere"),
                                           Vector3d::Constant(sphere.radius), 0, sphere.color));
  }
  for (const auto& capsule : frame.capsules) {
    requireFinite(capsule.center, "capsule centre");
    requireNonNegative(capsule.radius, "capsule radius");
    requireNonNegative(capsule.halfHeight, "capsule half height");
    batches.capsules.push_back(makeInstance(capsule.center - origin,
                                            normalizedOrientation(capsule.orientation, "capsule"),
                                            Vector3d::Constant(capsule.radius), capsule.halfHeight, capsule.color));
  }
}

void addMeshes(const debugdraw::Frame& frame, const Vector3d& origin, FrameBatches& batches) {
  std::map<const debugdraw::TriangleMesh*, std::size_t> batchOfMesh;  // lookup only; order comes from the frame
  for (const auto& solid : frame.meshes) {
    if (!solid.mesh) throw std::invalid_argument("debug draw: solid mesh has no mesh");
    requireFinite(solid.center, "mesh centre");
    auto [entry, inserted] = batchOfMesh.try_emplace(solid.mesh.get(), batches.meshes.size());
    if (inserted) batches.meshes.push_back(MeshBatch{solid.mesh.get(), {}});
    batches.meshes[entry->second].instances.push_back(makeInstance(
        solid.center - origin, normalizedOrientation(solid.orientation, "mesh"), Vector3d::Ones(), 0, solid.color));
  }
}

ColoredVertex coloredVertex(const Vector3d& relative, const Color& color) {
  ColoredVertex vertex{};
  copy(vertex.position, relative);
  copy(vertex.color, color);
  return vertex;
}

void addLine(const Vector3d& from, const Vector3d& to, const Color& color, const Vector3d& origin,
             FrameBatches& batches) {
  batches.lines.push_back(coloredVertex(from - origin, color));
  batches.lines.push_back(coloredVertex(to - origin, color));
}

// Pixel distance between two points relative to the origin; none when
// either lies behind the eye.
std::optional<double> screenLength(const ScreenMapping& screen, const Vector3d& from, const Vector3d& to) {
  const Eigen::Vector4d a = screen.viewProjection * from.homogeneous();
  const Eigen::Vector4d b = screen.viewProjection * to.homogeneous();
  if (!(a.w() > 0) || !(b.w() > 0)) return std::nullopt;
  const Eigen::Vector2d pixels(0.5 * screen.width, 0.5 * screen.height);
  const Eigen::Vector2d offset = (b.head<2>() / b.w() - a.head<2>() / a.w()).cwiseProduct(pixels);
  return offset.norm();
}

// The world length that spans the minimum on screen, never shorter than
// `length`. Perspective makes pixels per metre vary along the arrow, so the
// length is measured again after each growth.
double readableLength(const ScreenMapping* screen, const Vector3d& from, const Vector3d& direction,
                      double length) {
  if (!screen) return length;
  const double limit = length * kMaximumArrowGrowth;
  for (int pass = 0; pass < 4; ++pass) {
    const std::optional<double> pixels = screenLength(*screen, from, from + direction * length);
    if (!pixels || *pixels >= kMinimumArrowPixels - 1e-9) break;
    const double grown = std::min(limit, length * kMinimumArrowPixels / std::max(*pixels, 1e-9));
    if (!screenLength(*screen, from, from + direction * grown)) break;  // would reach behind the eye
    length = grown;
  }
  return length;
}

// A fifth of the arrow, but at least a few pixels so the direction reads.
double headLengthOf(const ScreenMapping* screen, const Vector3d& from, const Vector3d& direction, double length) {
  const double head = kHeadLengthFraction * length;
  if (!screen) return head;
  const std::optional<double> pixels = screenLength(*screen, from, from + direction * length);
  if (!pixels || *pixels <= 0) return head;
  return std::min(std::max(head, length * kMinimumArrowHeadPixels / *pixels), kMaximumHeadFraction * length);
}

// Four tenths of the head's length as seen: an arrow grown while seen end-on
// has a long head in the world, and its cone must not open into a disc that
// hides everything around it.
double headRadiusOf(const ScreenMapping* screen, const Vector3d& headBase, const Vector3d& direction,
                    double headLength) {
  const double radius = kHeadRadiusFraction * headLength;
  if (!screen) return radius;
  const std::optional<double> headPixels = screenLength(*screen, headBase, headBase + direction * headLength);
  const Vector3d across = direction.unitOrthogonal(), other = direction.cross(across);
  const std::optional<double> acrossPixels = screenLength(*screen, headBase, headBase + across * radius);
  const std::optional<double> otherPixels = screenLength(*screen, headBase, headBase + other * radius);
  if (!headPixels || !acrossPixels || !otherPixels) return radius;
  const double radiusPixels = std::max(*acrossPixels, *otherPixels);  // the cone's base as seen
  const double wantedPixels = kHeadRadiusFraction * std::max(*headPixels, kMinimumArrowHeadPixels);
  return radiusPixels > wantedPixels ? radius * wantedPixels / radiusPixels : radius;
}

void addArrow(const debugdraw::Arrow& arrow, const Vector3d& origin, const ScreenMapping* screen,
              FrameBatches& batches) {
  requireFinite(arrow.from, "arrow start");
  requireFinite(arrow.to, "arrow end");
  const Vector3d shaft = arrow.to - arrow.from;
  if (!(shaft.norm() > 0)) return;  // nothing to point with
  const Vector3d direction = shaft.normalized();
  const Vector3d from = arrow.from - origin;
  const double length = readableLength(screen, from, direction, shaft.norm());
  const double headLength = headLengthOf(screen, from, direction, length);
  const Vector3d headBase = from + direction * (length - headLength);
  batches.arrowShafts.push_back(coloredVertex(from, arrow.color));
  batches.arrowShafts.push_back(coloredVertex(headBase, arrow.color));
  const Quaterniond rotation = Quaterniond::FromTwoVectors(Vector3d::UnitY(), direction);
  const double headRadius = headRadiusOf(screen, headBase, direction, headLength);
  batches.arrowHeads.push_back(
      makeInstance(headBase, rotation, Vector3d(headRadius, headLength, headRadius), 0, arrow.color));
}

void addOverlays(const debugdraw::Frame& frame, const Vector3d& origin, const ScreenMapping* screen,
                 FrameBatches& batches) {
  for (const auto& box : frame.wireBoxes) batches.wireBoxes.push_back(boxInstance(box, origin, "wire box"));
  for (const auto& line : frame.lines) {
    requireFinite(line.from, "line start");
    requireFinite(line.to, "line end");
    addLine(line.from, line.to, line.color, origin, batches);
  }
  for (const auto& arrow : frame.arrows) addArrow(arrow, origin, screen, batches);
  for (const auto& point : frame.points) {
    requireFinite(point.position, "point");
    requireNonNegative(point.sizePixels, "point size");
    PointVertex vertex{};
    copy(vertex.position, point.position - origin);
    vertex.size = point.sizePixels;
    copy(vertex.color, point.color);
    batches.points.push_back(vertex);
  }
}

// Characters of texts and labels together: one budget, as a recording counts it.
void requireTextBudget(const debugdraw::Frame& frame) {
  std::size_t characters = 0;
  for (const auto& text : frame.texts) characters += text.text.size();
  for (const auto& label : frame.labels) characters += label.text.size();
  if (characters > debugdraw::maxFrameTextCharacters)
    throw std::invalid_argument("debug draw: " + std::to_string(characters) +
                                " characters of texts and labels, over the frame's limit of " +
                                std::to_string(debugdraw::maxFrameTextCharacters));
}

// Pixel position of a point relative to the origin; none when it lies outside
// the view's sides or nearer than its near plane (so behind a perspective eye).
std::optional<Eigen::Vector2d> pixelOf(const ScreenMapping& screen, const Vector3d& relative) {
  const Eigen::Vector4d clip = screen.viewProjection * relative.homogeneous();
  if (!(clip.w() > 0) || !(clip.z() >= -clip.w())) return std::nullopt;
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  if (!(ndc.cwiseAbs().maxCoeff() <= 1)) return std::nullopt;
  return Eigen::Vector2d((ndc.x() + 1) * 0.5 * screen.width, (1 - ndc.y()) * 0.5 * screen.height);
}

bool overlaps(const std::array<float, 4>& a, const std::array<float, 4>& b) {
  return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
}

// Labels in view, as screen-space text; every label is validated, seen or not.
// A label that yields (Label::yieldsToEarlier) is left out where it would
// cover one placed before it: in a crowd a few readable names beat an
// unreadable white mass, and the viewer puts highlighted bodies first.
std::vector<debugdraw::Text> placedLabels(const debugdraw::Frame& frame, const Vector3d& origin,
                                          const ScreenMapping* screen) {
  std::vector<debugdraw::Text> placed;
  std::vector<std::array<float, 4>> taken;
  for (const auto& label : frame.labels) {
    validateLabel(label);
    if (!screen) continue;
    const auto anchor = pixelOf(*screen, label.position - origin);
    if (!anchor) continue;
    debugdraw::Text text = labelText(label, *anchor);
    const std::array<float, 4> extent = textExtent(text);
    if (label.yieldsToEarlier &&
        std::any_of(taken.begin(), taken.end(), [&](const auto& other) { return overlaps(extent, other); }))
      continue;
    taken.push_back(extent);
    placed.push_back(std::move(text));
  }
  return placed;
}

// Labels first, so the screen's own text (the overlay) stays on top of them;
// within each, all outlines before any glyph.
void addTexts(const debugdraw::Frame& frame, const Vector3d& origin, const ScreenMapping* screen,
              FrameBatches& batches) {
  requireTextBudget(frame);
  const std::vector<debugdraw::Text> labels = placedLabels(frame, origin, screen);
  for (const auto& label : labels) appendTextOutline(label, batches.texts);
  for (const auto& label : labels) appendText(label, batches.texts);
  for (const auto& text : frame.texts) appendTextOutline(text, batches.texts);
  for (const auto& text : frame.texts) appendText(text, batches.texts);
}

}  // namespace

FrameBatches buildFrameBatches(const debugdraw::Frame& frame, const Vector3d& origin, const ScreenMapping* screen) {
  requireFinite(origin, "camera origin");
  FrameBatches batches;
  addSolids(frame, origin, batches);
  addMeshes(frame, origin, batches);
  addOverlays(frame, origin, screen, batches);
  addTexts(frame, origin, screen, batches);
  return batches;
}

}  // namespace physdbg::render
