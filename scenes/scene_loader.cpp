// JSON scene files. Every key is checked: unknown keys, wrong types, wrong
// vector lengths, out-of-range and non-finite numbers, and sizes past
// scenes/scene_limits.h are errors that name the file and the key path.
// Nothing is silently defaulted except absent keys.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/heightfield_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/colliders/triangle_mesh_collider.h"
#include "debugdraw/primitives.h"
#include "scenes/heightfield_image.h"
#include "scenes/json_reader.h"
#include "scenes/mesh_import.h"
#include "scenes/scene.h"
#include "scenes/scene_limits.h"

namespace physdbg {
namespace {

using nlohmann::json;
namespace limits = scene_limits;

std::shared_ptr<const Collider> readConvex(const JsonReader& reader, const json& parameters, const std::string& path) {
  reader.requireObject(parameters, path);
  reader.checkKeys(parameters, path, {"points"});
  const json& list = reader.array(reader.required(parameters, path, "points"), path + ".points", 0);
  if (list.size() > limits::maxHullPoints)
    reader.fail(path + ".points", "has " + std::to_string(list.size()) + " points (at most " +
                                      std::to_string(limits::maxHullPoints) + ")");
  std::vector<Vec3> points;
  points.reserve(list.size());
  for (std::size_t i = 0; i < list.size(); ++i)
    points.push_back(reader.vec3(list[i], path + ".points[" + std::to_string(i) + "]"));
  try {
    return std::make_shared<ConvexMeshCollider>(points);
  } catch (const std::invalid_argument& error) {
    reader.fail(path + ".points", error.what());
  }
}

// {"vertices": [[x, y, z], ...], "triangles": [[i, j, k], ...]}, sizes
// bounded before anything is built; indices checked here so that the error
// names the triangle's own key.
void readInlineMesh(const JsonReader& reader, const json& parameters, const std::string& path,
                    std::vector<Vec3>& vertices, std::vector<MeshTriangle>& triangles) {
  const json& vertexList = reader.array(reader.required(parameters, path, "vertices"), path + ".vertices", 0);
  const json& triangleList = reader.array(reader.required(parameters, path, "triangles"), path + ".triangles", 0);
  if (vertexList.size() > limits::maxMeshVertices)
    reader.fail(path + ".vertices", "has " + std::to_string(vertexList.size()) + " vertices (at most " +
                                        std::to_string(limits::maxMeshVertices) + ")");
  if (triangleList.size() > limits::maxMeshTriangles)
    reader.fail(path + ".triangles", "has " + std::to_string(triangleList.size()) + " triangles (at most " +
                                         std::to_string(limits::maxMeshTriangles) + ")");
  if (triangleList.empty()) reader.fail(path + ".triangles", "is empty: a mesh needs at least one triangle");
  vertices.reserve(vertexList.size());
  for (std::size_t i = 0; i < vertexList.size(); ++i)
    vertices.push_back(reader.vec3(vertexList[i], path + ".vertices[" + std::to_string(i) + "]"));
  triangles.reserve(triangleList.size());
  const auto lastVertex = static_cast<long long>(vertices.size()) - 1;
  for (std::size_t k = 0; k < triangleList.size(); ++k) {
    const std::string here = path + ".triangles[" + std::to_string(k) + "]";
    const json& corners = reader.array(triangleList[k], here, 3);
    MeshTriangle triangle;
    for (int c = 0; c < 3; ++c) {
      const std::string corner = here + "[" + std::to_string(c) + "]";
      if (lastVertex < 0) reader.fail(corner, "names a vertex, but the mesh has none");
      triangle[c] = static_cast<std::uint32_t>(reader.integer(corners[c], corner, 0, lastVertex));
    }
    triangles.push_back(triangle);
  }
}

// {"file": "level.obj", "scale": s or [x, y, z], "up_axis": "y" or "z",
// "nodes": ["name", ...]}: the path taken from the scene file's folder.
void readMeshFile(const JsonReader& reader, const json& parameters, const std::string& path,
                  std::vector<Vec3>& vertices, std::vector<MeshTriangle>& triangles, std::vector<std::string>& notes) {
  const std::filesystem::path named = reader.string(parameters["file"], path + ".file");
  const std::filesystem::path file =
      named.is_absolute() ? named : std::filesystem::path(reader.source()).parent_path() / named;
  MeshImportOptions options;
  options.maxTriangles = limits::maxMeshTriangles;
  options.maxFileBytes = limits::maxMeshFileBytes;
  if (parameters.contains("scale")) {
    const json& scale = parameters["scale"];
    options.scale = scale.is_array() ? reader.sizeVec3(scale, path + ".scale")
                                     : Vec3::Constant(reader.size(scale, path + ".scale"));
  }
  if (parameters.contains("up_axis")) {
    const std::string up = reader.string(parameters["up_axis"], path + ".up_axis");
    if (up != "y" && up != "z") reader.fail(path + ".up_axis", "must be \"y\" or \"z\", not '" + excerpt(up) + "'");
    options.zUp = up == "z";
  }
  if (parameters.contains("nodes")) {
    const json& list = reader.array(parameters["nodes"], path + ".nodes", 0);
    if (list.size() > limits::maxMeshNodes)
      reader.fail(path + ".nodes", "names " + std::to_string(list.size()) + " nodes (at most " +
                                       std::to_string(limits::maxMeshNodes) + ")");
    for (std::size_t i = 0; i < list.size(); ++i)
      options.nodes.push_back(reader.string(list[i], path + ".nodes[" + std::to_string(i) + "]"));
  }
  try {
    ImportedMesh mesh = importMesh(file.string(), options);
    vertices = std::move(mesh.vertices);
    triangles = std::move(mesh.triangles);
    if (mesh.skippedPrimitives > 0)
      notes.push_back(reader.source() + ": " + path + ": skipped " + std::to_string(mesh.skippedPrimitives) +
                      " points and lines of " + file.string());
  } catch (const MeshImportError& error) {
    reader.fail(path + ".file", "'" + file.string() + "': " + error.what());
  }
}

// "convex": true: the hull of the mesh's vertices, a shape a dynamic body
// can hold (a rock or a crate exported from a modelling tool).
std::shared_ptr<const Collider> convexHullOf(const JsonReader& reader, const std::string& path,
                                             std::vector<Vec3> vertices) {
  if (vertices.size() > limits::maxHullPoints)
    reader.fail(path, "has " + std::to_string(vertices.size()) + " vertices, more than a convex hull takes (" +
                          std::to_string(limits::maxHullPoints) + ")");
  try {
    return std::make_shared<ConvexMeshCollider>(std::move(vertices));
  } catch (const std::invalid_argument& error) {
    reader.fail(path + ".convex", error.what());
  }
}

// A triangle mesh given inline or by file; see scenes/README.md.
std::shared_ptr<const Collider> readMesh(const JsonReader& reader, const json& parameters, const std::string& path,
                                         std::vector<std::string>& notes) {
  reader.requireObject(parameters, path);
  reader.checkKeys(parameters, path,
                   {"vertices", "triangles", "active_edge_degrees", "file", "scale", "up_axis", "nodes", "convex"});
  std::vector<Vec3> vertices;
  std::vector<MeshTriangle> triangles;
  const bool inFile = parameters.contains("file");
  if (inFile && (parameters.contains("vertices") || parameters.contains("triangles")))
    reader.fail(path, "has both file and vertices or triangles: give one");
  if (!inFile)
    for (const char* key : {"scale", "up_axis", "nodes"})
      if (parameters.contains(key)) reader.fail(path + "." + key, "applies to a mesh file, and this mesh has none");
  if (inFile) readMeshFile(reader, parameters, path, vertices, triangles, notes);
  else readInlineMesh(reader, parameters, path, vertices, triangles);
  if (parameters.contains("convex") && reader.boolean(parameters["convex"], path + ".convex")) {
    if (parameters.contains("active_edge_degrees"))
      reader.fail(path + ".active_edge_degrees", "applies to a triangle mesh, not to \"convex\": true");
    return convexHullOf(reader, path, std::move(vertices));
  }
  double degrees = TriangleMeshCollider::defaultActiveEdgeDegrees;
  if (parameters.contains("active_edge_degrees"))
    degrees = reader.inRange(parameters["active_edge_degrees"], path + ".active_edge_degrees", 0.0, 180.0);
  const std::size_t given = triangles.size();
  try {
    auto mesh = std::make_shared<TriangleMeshCollider>(std::move(vertices), triangles, degrees);
    if (mesh->droppedTriangles() > 0)
      notes.push_back(reader.source() + ": " + path + ": dropped " + std::to_string(mesh->droppedTriangles()) +
                      " degenerate triangle" + (mesh->droppedTriangles() == 1 ? "" : "s") + " (no area) of " +
                      std::to_string(given));
    return mesh;
  } catch (const std::invalid_argument& error) {
    reader.fail(path, error.what());
  }
}

// {"samples": [[h, ...], ...] or "file": "terrain.png", "spacing": [dx, dz],
// "scale": s}: rows along z, columns along x; see scenes/README.md.
std::shared_ptr<const Collider> readHeightfield(const JsonReader& reader, const json& parameters,
                                                const std::string& path) {
  reader.requireObject(parameters, path);
  reader.checkKeys(parameters, path, {"samples", "file", "spacing", "scale", "active_edge_degrees"});
  if (parameters.contains("samples") == parameters.contains("file"))
    reader.fail(path, "needs samples or file (one of them)");
  std::vector<float> heights;
  int columns = 0, rows = 0;
  if (parameters.contains("file")) {
    const std::filesystem::path named = reader.string(parameters["file"], path + ".file");
    const std::filesystem::path file =
        named.is_absolute() ? named : std::filesystem::path(reader.source()).parent_path() / named;
    try {
      HeightfieldImage image = readHeightfieldImage(file.string(), limits::maxHeightfieldSamples);
      heights = std::move(image.heights);
      columns = image.columns;
      rows = image.rows;
    } catch (const HeightfieldImageError& error) {
      reader.fail(path + ".file", "'" + file.string() + "': " + error.what());
    }
  } else {
    const json& list = reader.array(parameters["samples"], path + ".samples", 0);
    rows = static_cast<int>(std::min<std::size_t>(list.size(), limits::maxHeightfieldSamples + 1));
    if (list.size() < 2) reader.fail(path + ".samples", "needs at least 2 rows");
    const json& first = reader.array(list[0], path + ".samples[0]", 0);
    columns = static_cast<int>(std::min<std::size_t>(first.size(), limits::maxHeightfieldSamples + 1));
    if (static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(columns) > limits::maxHeightfieldSamples)
      reader.fail(path + ".samples", "has " + std::to_string(list.size()) + " x " + std::to_string(first.size()) +
                                         " samples (at most " + std::to_string(limits::maxHeightfieldSamples) + ")");
    heights.reserve(static_cast<std::size_t>(rows) * columns);
    for (int row = 0; row < rows; ++row) {
      const std::string here = path + ".samples[" + std::to_string(row) + "]";
      const json& samples = reader.array(list[static_cast<std::size_t>(row)], here, static_cast<std::size_t>(columns));
      for (int column = 0; column < columns; ++column)
        heights.push_back(static_cast<float>(reader.number(samples[static_cast<std::size_t>(column)],
                                                           here + "[" + std::to_string(column) + "]")));
    }
  }
  const json& spacingValue = reader.required(parameters, path, "spacing");
  const json& spacing = reader.array(spacingValue, path + ".spacing", 2);
  const double dx = reader.size(spacing[0], path + ".spacing[0]"), dz = reader.size(spacing[1], path + ".spacing[1]");
  const double scale = parameters.contains("scale") ? reader.size(parameters["scale"], path + ".scale") : 1.0;
  double degrees = TriangleMeshCollider::defaultActiveEdgeDegrees;
  if (parameters.contains("active_edge_degrees"))
    degrees = reader.inRange(parameters["active_edge_degrees"], path + ".active_edge_degrees", 0.0, 180.0);
  try {
    return std::make_shared<HeightfieldCollider>(std::move(heights), columns, rows, dx, dz, scale, degrees);
  } catch (const std::invalid_argument& error) {
    reader.fail(path, error.what());
  }
}

std::shared_ptr<const Collider> readShape(const JsonReader& reader, const json& value, const std::string& path,
                                          std::vector<std::string>& notes) {
  reader.requireObject(value, path);
  if (value.size() != 1)
    reader.fail(path, "must have exactly one key naming the shape (sphere, box, capsule, convex, mesh, heightfield)");
  // Keep the iterator itself: key() and value() refer into the object, not into a temporary.
  const auto entry = value.begin();
  const std::string& kind = entry.key();
  const json& parameters = entry.value();
  const std::string here = JsonReader::child(path, kind);
  if (kind == "sphere") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"radius"});
    return std::make_shared<SphereCollider>(reader.size(reader.required(parameters, here, "radius"), here + ".radius"));
  }
  if (kind == "box") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"half_extents"});
    return std::make_shared<BoxCollider>(
        reader.sizeVec3(reader.required(parameters, here, "half_extents"), here + ".half_extents"));
  }
  if (kind == "capsule") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"radius", "half_height"});
    if (!parameters.contains("radius") || !parameters.contains("half_height"))
      reader.fail(here, "needs radius and half_height");
    return std::make_shared<CapsuleCollider>(reader.size(parameters["radius"], here + ".radius"),
                                             reader.nonNegative(parameters["half_height"], here + ".half_height"));
  }
  if (kind == "convex") return readConvex(reader, parameters, here);
  if (kind == "mesh") return readMesh(reader, parameters, here, notes);
  if (kind == "heightfield") return readHeightfield(reader, parameters, here);
  reader.fail(path, "unknown shape '" + excerpt(kind) + "' (known: sphere, box, capsule, convex, mesh, heightfield)");
}

void readBodyKeys(const JsonReader& reader, const json& value, const std::string& path, BodyDefinition& body) {
  const auto key = [&](const char* name) { return path + "." + name; };
  if (value.contains("name")) reader.string(value["name"], key("name"));
  if (value.contains("position")) body.position = reader.vec3(value["position"], key("position"));
  if (value.contains("orientation")) body.orientation = reader.quaternion(value["orientation"], key("orientation"));
  if (value.contains("velocity")) body.linearVelocity = reader.vec3(value["velocity"], key("velocity"));
  if (value.contains("angular_velocity"))
    body.angularVelocity = reader.vec3(value["angular_velocity"], key("angular_velocity"));
  if (value.contains("static")) body.isStatic = reader.boolean(value["static"], key("static"));
  if (value.contains("kinematic")) {
    body.isKinematic = reader.boolean(value["kinematic"], key("kinematic"));
    if (body.isKinematic && body.isStatic) reader.fail(key("kinematic"), "a body cannot be both static and kinematic");
  }
  if (value.contains("restitution"))
    body.material.restitution = reader.inRange(value["restitution"], key("restitution"), 0.0, 1.0);
  if (value.contains("static_friction"))
    body.material.staticFriction = reader.nonNegative(value["static_friction"], key("static_friction"));
  if (value.contains("dynamic_friction"))
    body.material.dynamicFriction = reader.nonNegative(value["dynamic_friction"], key("dynamic_friction"));
  if (value.contains("drag")) body.linearDrag = reader.nonNegative(value["drag"], key("drag"));
  if (value.contains("angular_drag")) body.angularDrag = reader.nonNegative(value["angular_drag"], key("angular_drag"));
  if (value.contains("use_gravity")) body.useGravity = reader.boolean(value["use_gravity"], key("use_gravity"));
  if (value.contains("lock_translation"))
    body.lockTranslation = reader.bool3(value["lock_translation"], key("lock_translation"));
  if (value.contains("lock_rotation")) body.lockRotation = reader.bool3(value["lock_rotation"], key("lock_rotation"));
}

// "density" in kg/m^3 gives the mass of the shape's volume, within the mass's bounds.
double massFromDensity(const JsonReader& reader, const json& value, const std::string& path, const Collider& shape) {
  const double density = reader.size(value, path);
  const double volume = shape.volume();
  const double mass = density * volume;
  if (!(mass >= limits::minSize && mass <= limits::maxMagnitude))
    reader.fail(path, "gives a mass of " + formatNumber(mass) + " kg (" + formatNumber(density) +
                          " kg/m^3 times the shape's volume, " + formatNumber(volume) + " m^3); a mass must be " +
                          formatNumber(limits::minSize) + " to " + formatNumber(limits::maxMagnitude) + " kg");
  return mass;
}

// [ixx, iyy, izz] (principal moments about the body axes) or a 3x3 array,
// kg m^2 about the centre of mass; inertiaTensorProblem says what is wrong.
Mat3 readInertia(const JsonReader& reader, const json& value, const std::string& path) {
  const json& rows = reader.array(value, path, 3);
  Mat3 inertia = Mat3::Zero();
  const bool matrix = rows[0].is_array();
  for (int i = 0; i < 3; ++i) {
    const std::string row = path + "[" + std::to_string(i) + "]";
    if (!matrix) {
      inertia(i, i) = reader.number(rows[i], row);
      if (!(inertia(i, i) > 0.0)) reader.fail(row, "must be positive, got " + formatNumber(inertia(i, i)));
      continue;
    }
    reader.array(rows[i], row, 3);
    for (int j = 0; j < 3; ++j) inertia(i, j) = reader.number(rows[i][j], row + "[" + std::to_string(j) + "]");
  }
  const std::string problem = inertiaTensorProblem(inertia);
  if (!problem.empty()) reader.fail(path, problem);
  return inertia;
}

// "mass" or "density", and "inertia", once static and kinematic are known.
// A static body ignores a mass or density (infinite); a kinematic body
// refuses them, and neither takes an inertia.
void readMassKeys(const JsonReader& reader, const json& value, const std::string& path, BodyDefinition& body) {
  const auto key = [&](const char* name) { return path + "." + name; };
  if (value.contains("mass") && value.contains("density"))
    reader.fail(path,
                "has both mass and density: give one (the mass of a density is density times the shape's volume)");
  if (value.contains("mass")) body.mass = reader.size(value["mass"], key("mass"));
  if (value.contains("density")) body.mass = massFromDensity(reader, value["density"], key("density"), *body.collider);
  for (const char* name : {"mass", "density"})
    if (body.isKinematic && value.contains(name))
      reader.fail(key(name), "a kinematic body has no mass: it moves with its velocities and pushes, unpushed");
  if (!value.contains("inertia")) return;
  if (body.isStatic || body.isKinematic)
    reader.fail(key("inertia"), std::string("a ") + (body.isStatic ? "static" : "kinematic") +
                                    " body has no inertia: nothing turns it");
  body.localInertia = readInertia(reader, value["inertia"], key("inertia"));
}

// "asleep": true starts a dynamic body asleep (World::sleep): still, so
// without a velocity, and in the run from the start.
bool readAsleep(const JsonReader& reader, const json& value, const std::string& path, const BodyDefinition& body,
                const std::optional<BodyLifetime>& lifetime) {
  if (!value.contains("asleep") || !reader.boolean(value["asleep"], path + ".asleep")) return false;
  if (body.isStatic || body.isKinematic)
    reader.fail(path + ".asleep", std::string("a ") + (body.isStatic ? "static" : "kinematic") +
                                      " body never sleeps; only a dynamic one can");
  if (body.linearVelocity != Vec3::Zero() || body.angularVelocity != Vec3::Zero())
    reader.fail(path + ".asleep",
                "a sleeping body is still: it cannot have a velocity or angular_velocity (one wakes it)");
  if (lifetime && lifetime->addAtStep > 0)
    reader.fail(path + ".asleep", "a body that joins the run later (add_at_step) joins it awake");
  return true;
}

// One body entry may expand to a grid of bodies ("repeat"): x varies fastest,
// then z, then y, so generated layers stack upwards in file order. The grid's
// size is checked against the scene's body limit before anything is added.
void addBody(const BodyDefinition& body, std::size_t entry, std::string name, SceneDescription& scene) {
  scene.bodies.push_back(body);
  scene.bodyEntries.push_back(entry);
  if (!name.empty() || !scene.bodyNames.empty()) scene.bodyNames.resize(scene.bodies.size());
  if (!name.empty()) scene.bodyNames.back() = std::move(name);
}

// A label over the body: printable ASCII, short enough to read on screen.
std::string readBodyName(const JsonReader& reader, const json& value, const std::string& path) {
  const std::string name = reader.string(value, path);
  if (name.empty() || name.size() > limits::maxBodyNameLength)
    reader.fail(path, "must have 1 to " + std::to_string(limits::maxBodyNameLength) + " characters, got " +
                          std::to_string(name.size()));
  for (const char c : name)
    if (c < 0x20 || c > 0x7e) reader.fail(path, "must be printable ASCII, got \"" + excerpt(name) + "\"");
  return name;
}

void expandRepeat(const JsonReader& reader, const json& repeat, const std::string& path, BodyDefinition body,
                  std::size_t entry, const std::string& name, SceneDescription& scene) {
  reader.requireObject(repeat, path);
  reader.checkKeys(repeat, path, {"count", "spacing"});
  if (!repeat.contains("count") || !repeat.contains("spacing")) reader.fail(path, "needs both count and spacing");
  reader.array(repeat["count"], path + ".count", 3);
  const long long room = limits::maxBodies - static_cast<long long>(scene.bodies.size());
  long long count[3];
  long long total = 1;
  for (int axis = 0; axis < 3; ++axis) {
    count[axis] =
        reader.integer(repeat["count"][axis], path + ".count[" + std::to_string(axis) + "]", 1, limits::maxBodies);
    total *= count[axis];  // each factor <= 1e6 and the running product <= 1e6: no overflow
    if (total > room)
      reader.fail(path + ".count", "makes more than " + std::to_string(limits::maxBodies) + " bodies in the scene");
  }
  const Vec3 spacing = reader.vec3(repeat["spacing"], path + ".spacing");
  const Vec3 origin = body.position;
  for (long long y = 0; y < count[1]; ++y)
    for (long long z = 0; z < count[2]; ++z)
      for (long long x = 0; x < count[0]; ++x) {
        body.position = origin + Vec3(x * spacing.x(), y * spacing.y(), z * spacing.z());
        if (!body.position.allFinite() || body.position.cwiseAbs().maxCoeff() > limits::maxMagnitude)
          reader.fail(path + ".spacing", "places a body farther than " + std::to_string(limits::maxMagnitude) +
                                              " m from the origin");
        const long long copy = (y * count[2] + z) * count[0] + x;
        addBody(body, entry, name.empty() ? "" : name + "[" + std::to_string(copy) + "]", scene);
      }
}

// "add_at_step": N, "remove_at_step": M: the body is in the run for the
// states N <= s < M (a state is the world after s steps).
std::optional<BodyLifetime> readLifetime(const JsonReader& reader, const json& value, const std::string& path) {
  if (!value.contains("add_at_step") && !value.contains("remove_at_step")) return std::nullopt;
  BodyLifetime lifetime;
  if (value.contains("add_at_step"))
    lifetime.addAtStep = static_cast<int>(reader.integer(value["add_at_step"], path + ".add_at_step", 0, limits::maxSteps - 1));
  if (value.contains("remove_at_step"))
    lifetime.removeAtStep = static_cast<int>(
        reader.integer(value["remove_at_step"], path + ".remove_at_step", lifetime.addAtStep + 1, limits::maxSteps));
  return lifetime;
}

// A filter's bits: a layer name, a list of names (declared in
// "collision_layers"), or the bits as a whole number.
std::uint32_t readLayerBits(const JsonReader& reader, const json& value, const std::string& path,
                            const std::vector<std::string>& names) {
  const auto bitOf = [&](const json& name, const std::string& where) {
    const std::string text = reader.string(name, where);
    const auto found = std::find(names.begin(), names.end(), text);
    if (found == names.end())
      reader.fail(where, "names layer '" + excerpt(text) + "', which \"collision_layers\" does not declare");
    return 1u << static_cast<unsigned>(found - names.begin());
  };
  if (value.is_string()) return bitOf(value, path);
  if (value.is_array()) {
    const json& list = reader.array(value, path, 0);
    if (list.size() > 32) reader.fail(path, "names more than 32 layers");
    std::uint32_t bits = 0;
    for (std::size_t i = 0; i < list.size(); ++i) bits |= bitOf(list[i], path + "[" + std::to_string(i) + "]");
    return bits;
  }
  return static_cast<std::uint32_t>(reader.integer(value, path, 0, 0xFFFFFFFFll));
}

void readFilterKeys(const JsonReader& reader, const json& value, const std::string& path,
                    const SceneDescription& scene, BodyDefinition& body) {
  if (value.contains("layer"))
    body.filter.layer = readLayerBits(reader, value["layer"], path + ".layer", scene.collisionLayers);
  if (value.contains("collides_with"))
    body.filter.collidesWith =
        readLayerBits(reader, value["collides_with"], path + ".collides_with", scene.collisionLayers);
  if (value.contains("sensor")) body.isSensor = reader.boolean(value["sensor"], path + ".sensor");
}

void readCollisionLayers(const JsonReader& reader, const json& value, SceneDescription& scene) {
  const json& list = reader.array(value, "collision_layers", 0);
  if (list.size() > 32) reader.fail("collision_layers", "declares " + std::to_string(list.size()) + " layers (at most 32, one a bit)");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string where = "collision_layers[" + std::to_string(i) + "]";
    std::string name = reader.string(list[i], where);
    if (name.empty() || name.size() > limits::maxBodyNameLength)
      reader.fail(where, "must be 1 to " + std::to_string(limits::maxBodyNameLength) + " characters");
    if (std::find(scene.collisionLayers.begin(), scene.collisionLayers.end(), name) != scene.collisionLayers.end())
      reader.fail(where, "declares '" + excerpt(name) + "' twice");
    scene.collisionLayers.push_back(std::move(name));
  }
}

void readBody(const JsonReader& reader, const json& value, std::size_t entry, SceneDescription& scene) {
  const std::string path = "bodies[" + std::to_string(entry) + "]";
  reader.requireObject(value, path);
  reader.checkKeys(value, path,
                   {"name", "shape", "position", "orientation", "velocity", "angular_velocity", "mass", "static",
                    "restitution", "static_friction", "dynamic_friction", "drag", "angular_drag", "use_gravity",
                    "lock_translation", "lock_rotation", "repeat", "kinematic", "add_at_step", "remove_at_step",
                    "density", "inertia", "asleep", "layer", "collides_with", "sensor"});
  BodyDefinition body;
  body.collider = readShape(reader, reader.required(value, path, "shape"), path + ".shape", scene.notes);
  readBodyKeys(reader, value, path, body);
  readFilterKeys(reader, value, path, scene, body);
  const ColliderKind kind = body.collider->kind();
  if ((kind == ColliderKind::TriangleMesh || kind == ColliderKind::Heightfield) && !body.isStatic && !body.isKinematic)
    reader.fail(path + ".shape." + colliderKindName(kind),
                std::string("a ") + colliderKindName(kind) +
                    " has no volume and no inside, so it cannot be dynamic: give the body \"static\": true or "
                    "\"kinematic\": true");
  readMassKeys(reader, value, path, body);
  body = aboutCentreOfMass(body);  // the scene states the body where its centre of mass is
  const std::string name = value.contains("name") ? readBodyName(reader, value["name"], path + ".name") : "";
  const std::optional<BodyLifetime> lifetime = readLifetime(reader, value, path);
  const bool asleep = readAsleep(reader, value, path, body, lifetime);
  const std::size_t first = scene.bodies.size();
  if (value.contains("repeat")) {
    expandRepeat(reader, value["repeat"], path + ".repeat", body, entry, name, scene);
  } else {
    if (static_cast<long long>(scene.bodies.size()) >= limits::maxBodies)
      reader.fail(path, "makes more than " + std::to_string(limits::maxBodies) + " bodies in the scene");
    addBody(body, entry, name, scene);
  }
  for (std::size_t id = first; asleep && id < scene.bodies.size(); ++id)
    scene.sleeping.push_back(static_cast<BodyId>(id));
  if (!lifetime) return;
  for (std::size_t id = first; id < scene.bodies.size(); ++id) {
    scene.lifetimes.push_back(*lifetime);
    scene.lifetimes.back().body = static_cast<BodyId>(id);
  }
}

int readCount(const JsonReader& reader, const json& value, const std::string& path, int high) {
  return static_cast<int>(reader.integer(value, path, 1, high));
}

// A string that must be one of `choices`; the message lists them all.
template <typename Value>
Value readChoice(const JsonReader& reader, const json& value, const std::string& path,
                 std::initializer_list<std::pair<const char*, Value>> choices) {
  const std::string text = reader.string(value, path);
  std::string names;
  for (const auto& choice : choices) {
    if (text == choice.first) return choice.second;
    names += (names.empty() ? "\"" : ", \"") + std::string(choice.first) + "\"";
  }
  reader.fail(path, "must be one of " + names + ", got \"" + excerpt(text) + "\"");
}

void readSolver(const JsonReader& reader, const json& value, const std::string& path, SolverSettings& solver) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path,
                   {"kind", "iterations", "substeps", "max_substeps", "calm_substeps", "calm_speed", "slop",
                    "bounce_threshold", "position_correction"});
  if (value.contains("kind"))
    solver.kind = readChoice<SolverKind>(reader, value["kind"], path + ".kind",
                                         {{solverKindName(SolverKind::Seed), SolverKind::Seed},
                                          {solverKindName(SolverKind::SequentialImpulse), SolverKind::SequentialImpulse}});
  if (value.contains("slop")) solver.linearSlop = reader.inRange(value["slop"], path + ".slop", 0.0, 1.0);
  if (value.contains("bounce_threshold"))
    solver.restitutionThreshold = reader.inRange(value["bounce_threshold"], path + ".bounce_threshold", 0.0, 1e3);
  if (value.contains("position_correction")) {
    if (solver.kind != SolverKind::Seed)
      reader.fail(path + ".position_correction", "applies to the seed solver only (set \"kind\": \"seed\")");
    solver.seed.positionCorrection =
        reader.inRange(value["position_correction"], path + ".position_correction", 0.0, 1.0);
  }
  if (value.contains("iterations"))
    solver.velocityIterations = readCount(reader, value["iterations"], path + ".iterations", limits::maxIterations);
  if (value.contains("substeps"))
    solver.substeps = readCount(reader, value["substeps"], path + ".substeps", limits::maxSubsteps);
  if (value.contains("max_substeps")) {
    solver.maxSubsteps = readCount(reader, value["max_substeps"], path + ".max_substeps", limits::maxSubsteps);
    if (solver.maxSubsteps < solver.substeps)
      reader.fail(path + ".max_substeps",
                  "must be at least substeps (" + std::to_string(solver.substeps) + "), got " +
                      std::to_string(solver.maxSubsteps));
  }
  if (value.contains("calm_substeps"))
    solver.calmSubsteps = readCount(reader, value["calm_substeps"], path + ".calm_substeps", limits::maxSubsteps);
  if (value.contains("calm_speed"))
    solver.calmSpeed = reader.inRange(value["calm_speed"], path + ".calm_speed", 0.0, 1e3);
  const long long sweeps = static_cast<long long>(std::max(solver.substeps, solver.maxSubsteps)) *
                           solver.velocityIterations;
  if (sweeps > limits::maxSweepsPerStep)
    reader.fail(path, "asks for up to " + std::to_string(sweeps) + " contact sweeps per step (max_substeps x " +
                          "iterations; at most " + std::to_string(limits::maxSweepsPerStep) + ")");
}

SceneCamera readCamera(const JsonReader& reader, const json& value, const std::string& path) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"eye", "target", "fov", "orthographic"});
  SceneCamera camera;
  if (value.contains("eye")) camera.eye = reader.vec3(value["eye"], path + ".eye");
  if (value.contains("target")) camera.target = reader.vec3(value["target"], path + ".target");
  if (value.contains("fov")) camera.fovYDegrees = reader.inRange(value["fov"], path + ".fov", 1.0, 170.0);
  if (value.contains("orthographic")) camera.orthographic = reader.boolean(value["orthographic"], path + ".orthographic");
  if (camera.eye && camera.target && (*camera.eye - *camera.target).norm() <= 1e-9 * camera.eye->norm())
    reader.fail(path, "eye and target must differ");
  return camera;
}

CombineRule readCombineRule(const JsonReader& reader, const json& value, const std::string& path) {
  return readChoice<CombineRule>(reader, value, path,
                                 {{"average", CombineRule::Average},
                                  {"minimum", CombineRule::Minimum},
                                  {"maximum", CombineRule::Maximum},
                                  {"multiply", CombineRule::Multiply},
                                  {"geometric_mean", CombineRule::GeometricMean}});
}

BroadPhaseKind readBroadPhaseKind(const JsonReader& reader, const json& value, const std::string& path) {
  return readChoice<BroadPhaseKind>(reader, value, path,
                                    {{"tree", BroadPhaseKind::Tree}, {"brute_force", BroadPhaseKind::BruteForce}});
}

// "tree" | "brute_force", or an object that also sets the tree's insertion
// and rotations, the fat margin and static-pair skipping.
void readBroadPhase(const JsonReader& reader, const json& value, const std::string& path, WorldSettings& world) {
  if (!value.is_object()) {
    world.broadPhase = readBroadPhaseKind(reader, value, path);
    return;
  }
  reader.checkKeys(value, path, {"kind", "insertion", "rotations", "fat_margin", "skip_static_pairs"});
  if (value.contains("kind")) world.broadPhase = readBroadPhaseKind(reader, value["kind"], path + ".kind");
  const bool tree = world.broadPhase == BroadPhaseKind::Tree;
  for (const char* key : {"insertion", "rotations"})
    if (value.contains(key) && !tree) reader.fail(path + "." + key, "applies to the tree only (\"kind\": \"tree\")");
  if (value.contains("insertion"))
    world.treeInsertion = readChoice<InsertionMethod>(
        reader, value["insertion"], path + ".insertion",
        {{"branch_and_bound", InsertionMethod::BranchAndBound}, {"greedy", InsertionMethod::Greedy}});
  if (value.contains("rotations")) world.treeRotations = reader.boolean(value["rotations"], path + ".rotations");
  if (value.contains("fat_margin"))
    world.fatMargin = reader.inRange(value["fat_margin"], path + ".fat_margin", 0.0, limits::maxFatMargin);
  if (value.contains("skip_static_pairs"))
    world.skipStaticPairs = reader.boolean(value["skip_static_pairs"], path + ".skip_static_pairs");
}

void readCollision(const JsonReader& reader, const json& value, const std::string& path, WorldSettings& world) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"device", "reuse_contacts"});
  if (value.contains("device"))
    world.collisionDevice = readChoice<CollisionDevice>(reader, value["device"], path + ".device",
                                                        {{"cpu", CollisionDevice::Cpu}, {"gpu", CollisionDevice::Gpu}});
  if (value.contains("reuse_contacts"))
    world.reuseContacts = reader.boolean(value["reuse_contacts"], path + ".reuse_contacts");
}

void readWorldKeys(const JsonReader& reader, const json& root, SceneDescription& scene) {
  if (root.contains("gravity")) scene.world.gravity = reader.vec3(root["gravity"], "gravity");
  if (root.contains("dt")) scene.world.dt = reader.inRange(root["dt"], "dt", limits::minDt, limits::maxDt);
  if (root.contains("steps")) scene.steps = static_cast<int>(reader.integer(root["steps"], "steps", 1, limits::maxSteps));
  if (root.contains("allow_sleep")) scene.world.allowSleep = reader.boolean(root["allow_sleep"], "allow_sleep");
  if (root.contains("time_of_impact"))
    scene.world.castFastPairs = reader.boolean(root["time_of_impact"], "time_of_impact");
  if (root.contains("threads"))
    scene.world.threads = static_cast<int>(reader.integer(root["threads"], "threads", 0, limits::maxThreads));
  if (root.contains("broadphase")) readBroadPhase(reader, root["broadphase"], "broadphase", scene.world);
  if (root.contains("collision")) readCollision(reader, root["collision"], "collision", scene.world);
  if (root.contains("solver")) readSolver(reader, root["solver"], "solver", scene.world.solver);
  if (root.contains("restitution_combine"))
    scene.world.solver.combine.restitution = readCombineRule(reader, root["restitution_combine"], "restitution_combine");
  if (root.contains("friction_combine"))
    scene.world.solver.combine.friction = readCombineRule(reader, root["friction_combine"], "friction_combine");
}

ForceMode readForceMode(const JsonReader& reader, const json& value, const std::string& path) {
  return readChoice<ForceMode>(reader, value, path,
                               {{"force", ForceMode::Force},
                                {"acceleration", ForceMode::Acceleration},
                                {"impulse", ForceMode::Impulse},
                                {"velocity_change", ForceMode::VelocityChange}});
}

// An entry's "body": an index into the scene's bodies after `repeat`.
BodyId readBodyIndex(const JsonReader& reader, const json& value, const std::string& path,
                     const SceneDescription& scene) {
  const long long bodies = static_cast<long long>(scene.bodies.size());
  if (bodies == 0) reader.fail(path + ".body", "the scene has no bodies");
  return static_cast<BodyId>(reader.integer(reader.required(value, path, "body"), path + ".body", 0, bodies - 1));
}

// {"body": I, "force" | "torque": [x,y,z], "mode", "at", "steps": [A, B]}:
// the body must exist (after `repeat`) and be dynamic.
ScheduledForce readForce(const JsonReader& reader, const json& value, const std::string& path,
                         const SceneDescription& scene) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"body", "force", "torque", "mode", "at", "steps"});
  ScheduledForce force;
  force.body = readBodyIndex(reader, value, path, scene);
  const BodyDefinition& body = scene.bodies[force.body];
  if (body.isStatic || body.isKinematic)
    reader.fail(path + ".body", "body " + std::to_string(force.body) + " is " +
                                    (body.isStatic ? "static" : "kinematic") + ": forces cannot move it");
  if (value.contains("force") == value.contains("torque")) reader.fail(path, "needs exactly one of force and torque");
  force.isTorque = value.contains("torque");
  const char* vectorKey = force.isTorque ? "torque" : "force";
  force.vector = reader.vec3(value[vectorKey], path + "." + vectorKey);
  if (value.contains("mode")) force.mode = readForceMode(reader, value["mode"], path + ".mode");
  if (value.contains("at")) {
    if (force.isTorque) reader.fail(path + ".at", "a torque has no point of application");
    force.at = reader.vec3(value["at"], path + ".at");
  }
  if (value.contains("steps")) {
    const json& steps = reader.array(value["steps"], path + ".steps", 2);
    force.firstStep = static_cast<int>(reader.integer(steps[0], path + ".steps[0]", 0, limits::maxSteps - 1));
    force.endStep = static_cast<int>(reader.integer(steps[1], path + ".steps[1]", force.firstStep + 1,
                                                     limits::maxSteps));
  }
  return force;
}

// A top-level list of at most `most` entries ("forces", "set"), each read by
// `read(reader, entry, "key[i]", scene)` after the bodies.
template <typename Entry>
void readEntries(const JsonReader& reader, const json& value, const std::string& key, std::size_t most,
                 Entry (*read)(const JsonReader&, const json&, const std::string&, const SceneDescription&),
                 const SceneDescription& scene, std::vector<Entry>& entries) {
  const json& list = reader.array(value, key, 0);
  if (list.size() > most)
    reader.fail(key, "has " + std::to_string(list.size()) + " entries (at most " + std::to_string(most) + ")");
  for (std::size_t i = 0; i < list.size(); ++i)
    entries.push_back(read(reader, list[i], key + "[" + std::to_string(i) + "]", scene));
}

// {"body": I, "step": N, "position", "orientation", "velocity",
// "angular_velocity"}: at least one of the four, for a body that is not static.
ScheduledState readState(const JsonReader& reader, const json& value, const std::string& path,
                         const SceneDescription& scene) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"body", "step", "position", "orientation", "velocity", "angular_velocity"});
  ScheduledState state;
  state.body = readBodyIndex(reader, value, path, scene);
  if (scene.bodies[state.body].isStatic)
    reader.fail(path + ".body", "body " + std::to_string(state.body) + " is static: its state cannot be set");
  state.step =
      static_cast<int>(reader.integer(reader.required(value, path, "step"), path + ".step", 0, limits::maxSteps - 1));
  if (value.contains("position")) state.position = reader.vec3(value["position"], path + ".position");
  if (value.contains("orientation")) state.orientation = reader.quaternion(value["orientation"], path + ".orientation");
  if (value.contains("velocity")) state.linearVelocity = reader.vec3(value["velocity"], path + ".velocity");
  if (value.contains("angular_velocity"))
    state.angularVelocity = reader.vec3(value["angular_velocity"], path + ".angular_velocity");
  if (!state.position && !state.orientation && !state.linearVelocity && !state.angularVelocity)
    reader.fail(path, "needs at least one of position, orientation, velocity and angular_velocity");
  return state;
}

}  // namespace

SceneDescription parseScene(const std::string& jsonText, const std::string& sourceName) {
  const JsonReader reader(sourceName);
  const json root = parseBoundedJson(jsonText, sourceName);
  reader.requireObject(root, "");
  reader.checkKeys(
      root, "",
      {"name", "description", "gravity", "dt", "steps", "bodies", "camera", "layers", "allow_sleep", "threads",
       "broadphase", "collision", "solver", "restitution_combine", "friction_combine", "forces", "set",
       "time_of_impact", "collision_layers"});
  SceneDescription scene;
  scene.source = sourceName;
  scene.name = std::filesystem::path(sourceName).stem().string();
  if (root.contains("name")) scene.name = reader.string(root["name"], "name");
  if (root.contains("description")) scene.description = reader.string(root["description"], "description");
  readWorldKeys(reader, root, scene);
  if (root.contains("camera")) scene.camera = readCamera(reader, root["camera"], "camera");
  if (root.contains("layers")) {
    scene.layers = reader.string(root["layers"], "layers");
    try {
      debugdraw::parseLayers(*scene.layers);
    } catch (const std::invalid_argument& error) {
      reader.fail("layers", error.what());  // parseLayers quotes only a short piece
    }
  }
  if (root.contains("collision_layers")) readCollisionLayers(reader, root["collision_layers"], scene);
  const json& bodies = reader.array(reader.required(root, "", "bodies"), "bodies", 0);
  for (std::size_t i = 0; i < bodies.size(); ++i) readBody(reader, bodies[i], i, scene);
  if (root.contains("forces"))
    readEntries(reader, root["forces"], "forces", limits::maxForces, readForce, scene, scene.forces);
  if (root.contains("set")) readEntries(reader, root["set"], "set", limits::maxStates, readState, scene, scene.states);
  return scene;
}

SceneDescription loadSceneFile(const std::string& path) {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error) throw SceneError(path + ": cannot read scene file: " + error.message());
  if (bytes > limits::maxFileBytes)
    throw SceneError(path + ": scene file of " + std::to_string(bytes) + " bytes (at most " +
                     std::to_string(limits::maxFileBytes) + ")");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw SceneError(path + ": cannot open scene file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw SceneError(path + ": cannot read scene file");
  if (text.str().size() > limits::maxFileBytes) throw SceneError(path + ": scene file grew while being read");
  return parseScene(text.str(), path);
}

}  // namespace physdbg
