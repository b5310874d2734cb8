#include "render/unit_meshes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace physdbg::render {
namespace {

using Eigen::Vector3f;

MeshVertex vertex(const Vector3f& position, const Vector3f& normal, float stretch = 0) {
  return MeshVertex{{position.x(), position.y(), position.z(), stretch}, {normal.x(), normal.y(), normal.z()}};
}

void addTriangle(UnitMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// Degenerate triangles get some normal; they cover no pixels anyway.
Vector3f faceNormal(const Vector3f& a, const Vector3f& b, const Vector3f& c) {
  const Vector3f cross = (b - a).cross(c - a);
  return cross.norm() > 0 ? Vector3f(cross.normalized()) : Vector3f::UnitY();
}

// Appends a flat triangle with its own three vertices.
void addFlatTriangle(UnitMesh& mesh, const Vector3f& a, const Vector3f& b, const Vector3f& c) {
  const Vector3f normal = faceNormal(a, b, c);
  const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const Vector3f* corner : {&a, &b, &c}) mesh.vertices.push_back(vertex(*corner, normal));
  addTriangle(mesh, first, first + 1, first + 2);
}

}  // namespace

UnitMesh unitCube() {
  UnitMesh mesh;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Vector3f normal = Vector3f::Zero();
      normal[axis] = sign;
      const Vector3f u = Vector3f::Unit((axis + 1) % 3), v = Vector3f::Unit((axis + 2) % 3);
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      for (const auto& [du, dv] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}})
        mesh.vertices.push_back(vertex(normal + du * u + dv * v, normal));
      // u x v = +normal: counter-clockwise seen from outside when sign > 0.
      if (sign > 0) {
        addTriangle(mesh, first, first + 1, first + 2);
        addTriangle(mesh, first, first + 2, first + 3);
      } else {
        addTriangle(mesh, first, first + 2, first + 1);
        addTriangle(mesh, first, first + 3, first + 2);
      }
    }
  }
  return mesh;
}

UnitMesh unitCubeEdges() {
  UnitMesh mesh;
  for (int corner = 0; corner < 8; ++corner) {
    const Vector3f position((corner & 1) ? 1.f : -1.f, (corner & 2) ? 1.f : -1.f, (corner & 4) ? 1.f : -1.f);
    mesh.vertices.push_back(vertex(position, Vector3f::Zero()));
  }
  for (std::uint32_t corner = 0; corner < 8; ++corner)
    for (std::uint32_t bit : {1u, 2u, 4u})
      if ((corner & bit) == 0) mesh.indices.insert(mesh.indices.end(), {corner, corner | bit});
  return mesh;
}

UnitMesh capsuleSphere(int segments, int rings) {
  if (segments < 3 || rings < 2 || rings % 2 != 0)
    throw std::invalid_argument("capsuleSphere: need segments >= 3 and an even ring count >= 2");
  UnitMesh mesh;
  const int columns = segments + 1;
  // Rows 0..rings/2 are the upper half, rows rings/2+1..rings+1 the lower half;
  // the equator appears twice so the capsule's cylinder stretches between.
  const int rows = rings + 2;
  for (int row = 0; row < rows; ++row) {
    const int ring = row <= rings / 2 ? row : row - 1;
    const float stretch = row <= rings / 2 ? 1.0f : -1.0f;
    const double polar = std::numbers::pi * ring / rings;
    for (int column = 0; column < columns; ++column) {
      const double azimuth = 2.0 * std::numbers::pi * column / segments;
      const Vector3f normal(static_cast<float>(std::sin(polar) * std::cos(azimuth)), static_cast<float>(std::cos(polar)),
                            static_cast<float>(-std::sin(polar) * std::sin(azimuth)));
      mesh.vertices.push_back(vertex(normal, normal, stretch));
    }
  }
  for (int row = 0; row + 1 < rows; ++row) {
    for (int column = 0; column < segments; ++column) {
      const auto a = static_cast<std::uint32_t>(row * columns + column), b = a + 1;
      const auto c = a + static_cast<std::uint32_t>(columns), d = c + 1;
      addTriangle(mesh, a, c, b);
      addTriangle(mesh, b, c, d);
    }
  }
  return mesh;
}

UnitMesh unitCone(int segments) {
  if (segments < 3) throw std::invalid_argument("unitCone: need at least 3 segments");
  UnitMesh mesh;
  const Vector3f apex = Vector3f::UnitY();
  auto rim = [segments](int index) {
    const double angle = 2.0 * std::numbers::pi * index / segments;
    return Vector3f(static_cast<float>(std::cos(angle)), 0.0f, static_cast<float>(-std::sin(angle)));
  };
  // Two rings of rim points (rim(segments) is kept apart from rim(0): the same
  // floats as one triangle per face had), the apex and the base centre.
  // Side face i is (rim i, rim i+1, apex) with its normal on rim i of the
  // side ring; base face i is (rim i+1, rim i, centre) with the base normal
  // on rim i+1 of the base ring.
  const auto sideRing = static_cast<std::uint32_t>(0), baseRing = static_cast<std::uint32_t>(segments + 1);
  const auto apexIndex = static_cast<std::uint32_t>(2 * (segments + 1)), centreIndex = apexIndex + 1;
  for (int index = 0; index <= segments; ++index)
    mesh.vertices.push_back(vertex(rim(index), faceNormal(rim(index), rim(index + 1), apex)));
  for (int index = 0; index <= segments; ++index)
    mesh.vertices.push_back(vertex(rim(index), faceNormal(rim(index), rim(index - 1), Vector3f::Zero())));
  mesh.vertices.push_back(vertex(apex, Vector3f::UnitY()));
  mesh.vertices.push_back(vertex(Vector3f::Zero(), -Vector3f::UnitY()));
  for (int index = 0; index < segments; ++index) {
    const auto i = static_cast<std::uint32_t>(index);
    addTriangle(mesh, sideRing + i, sideRing + i + 1, apexIndex);
    addTriangle(mesh, baseRing + i + 1, baseRing + i, centreIndex);
  }
  return mesh;
}

UnitMesh flatShadedMesh(const debugdraw::TriangleMesh& source) {
  if (source.indices.size() % 3 != 0)
    throw std::invalid_argument("triangle mesh " + std::to_string(source.id) + ": index count " +
                                std::to_string(source.indices.size()) + " is not a multiple of 3");
  for (std::uint32_t index : source.indices)
    if (index >= source.vertices.size())
      throw std::invalid_argument("triangle mesh " + std::to_string(source.id) + ": index " + std::to_string(index) +
                                  " out of range (" + std::to_string(source.vertices.size()) + " vertices)");
  UnitMesh mesh;
  for (std::size_t first = 0; first < source.indices.size(); first += 3)
    addFlatTriangle(mesh, source.vertices[source.indices[first]], source.vertices[source.indices[first + 1]],
                    source.vertices[source.indices[first + 2]]);
  return mesh;
}

}  // namespace physdbg::render
