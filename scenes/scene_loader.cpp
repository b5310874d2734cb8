// JSON scene files. Every key is checked: unknown keys, wrong types, wrong
// vector lengths, out-of-range and non-finite numbers are errors that name the
// file and the key path. Nothing is silently defaulted except absent keys.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/capsule_collider.h"
#include "engine/colliders/convex_mesh_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

using nlohmann::json;

class SceneReader {
 public:
  explicit SceneReader(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneError(source_ + ": " + (path.empty() ? "" : path + ": ") + what);
  }

  void requireObject(const json& value, const std::string& path) const {
    if (!value.is_object()) fail(path, "must be an object, got " + typeName(value));
  }

  void checkKeys(const json& object, const std::string& path, const std::set<std::string>& allowed) const {
    for (const auto& [key, value] : object.items()) {
      if (allowed.count(key)) continue;
      std::string list;
      for (const auto& name : allowed) list += (list.empty() ? "" : ", ") + name;
      fail(path.empty() ? key : path + "." + key, "unknown key (allowed here: " + list + ")");
    }
  }

  double number(const json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "must be a number, got " + typeName(value));
    const double result = value.get<double>();
    if (!std::isfinite(result)) fail(path, "must be finite");
    return result;
  }

  double positive(const json& value, const std::string& path) const {
    const double result = number(value, path);
    if (!(result > 0.0)) fail(path, "must be positive, got " + value.dump());
    return result;
  }

  double nonNegative(const json& value, const std::string& path) const {
    const double result = number(value, path);
    if (result < 0.0) fail(path, "must not be negative, got " + value.dump());
    return result;
  }

  double inRange(const json& value, const std::string& path, double low, double high) const {
    const double result = number(value, path);
    if (result < low || result > high) {
      std::ostringstream message;
      message << "must be between " << low << " and " << high << ", got " << value.dump();
      fail(path, message.str());
    }
    return result;
  }

  int positiveInteger(const json& value, const std::string& path) const {
    if (!value.is_number_integer()) fail(path, "must be an integer, got " + value.dump());
    const auto result = value.get<long long>();
    if (result <= 0 || result > 100'000'000) fail(path, "must be a positive integer, got " + value.dump());
    return static_cast<int>(result);
  }

  bool boolean(const json& value, const std::string& path) const {
    if (!value.is_boolean()) fail(path, "must be true or false, got " + typeName(value));
    return value.get<bool>();
  }

  std::string string(const json& value, const std::string& path) const {
    if (!value.is_string()) fail(path, "must be a string, got " + typeName(value));
    return value.get<std::string>();
  }

  const json& array(const json& value, const std::string& path, std::size_t length) const {
    if (!value.is_array()) fail(path, "must be an array, got " + typeName(value));
    if (length != 0 && value.size() != length)
      fail(path, "must have " + std::to_string(length) + " elements, got " + std::to_string(value.size()));
    return value;
  }

  Vec3 vec3(const json& value, const std::string& path) const {
    array(value, path, 3);
    return {number(value[0], path + "[0]"), number(value[1], path + "[1]"), number(value[2], path + "[2]")};
  }

  Vec3 positiveVec3(const json& value, const std::string& path) const {
    array(value, path, 3);
    return {positive(value[0], path + "[0]"), positive(value[1], path + "[1]"), positive(value[2], path + "[2]")};
  }

  Quat quaternion(const json& value, const std::string& path) const {
    array(value, path, 4);
    const Quat q(number(value[0], path + "[0]"), number(value[1], path + "[1]"), number(value[2], path + "[2]"),
                 number(value[3], path + "[3]"));
    if (q.norm() < 1e-9) fail(path, "must not be a zero quaternion (use [1,0,0,0] for no rotation)");
    return q.normalized();
  }

  std::array<bool, 3> bool3(const json& value, const std::string& path) const {
    array(value, path, 3);
    return {boolean(value[0], path + "[0]"), boolean(value[1], path + "[1]"), boolean(value[2], path + "[2]")};
  }

  static std::string typeName(const json& value) {
    if (value.is_number()) return "a number";
    if (value.is_boolean()) return "a boolean";
    if (value.is_string()) return "a string";
    if (value.is_array()) return "an array";
    if (value.is_object()) return "an object";
    return "null";
  }

 private:
  std::string source_;
};

std::shared_ptr<const Collider> readConvex(const SceneReader& reader, const json& parameters, const std::string& path) {
  reader.requireObject(parameters, path);
  reader.checkKeys(parameters, path, {"points"});
  if (!parameters.contains("points")) reader.fail(path, "missing key points");
  const json& list = reader.array(parameters["points"], path + ".points", 0);
  if (list.size() > 100000) reader.fail(path + ".points", "more than 100000 points");
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < list.size(); ++i)
    points.push_back(reader.vec3(list[i], path + ".points[" + std::to_string(i) + "]"));
  try {
    return std::make_shared<ConvexMeshCollider>(points);
  } catch (const std::invalid_argument& error) {
    reader.fail(path + ".points", error.what());
  }
}

std::shared_ptr<const Collider> readShape(const SceneReader& reader, const json& value, const std::string& path) {
  reader.requireObject(value, path);
  if (value.size() != 1)
    reader.fail(path, "must have exactly one key naming the shape (sphere, box, capsule, convex)");
  const auto& [kind, parameters] = *value.items().begin();
  const std::string here = path + "." + kind;
  if (kind == "sphere") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"radius"});
    if (!parameters.contains("radius")) reader.fail(here, "missing key radius");
    return std::make_shared<SphereCollider>(reader.positive(parameters["radius"], here + ".radius"));
  }
  if (kind == "box") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"half_extents"});
    if (!parameters.contains("half_extents")) reader.fail(here, "missing key half_extents");
    return std::make_shared<BoxCollider>(reader.positiveVec3(parameters["half_extents"], here + ".half_extents"));
  }
  if (kind == "capsule") {
    reader.requireObject(parameters, here);
    reader.checkKeys(parameters, here, {"radius", "half_height"});
    if (!parameters.contains("radius") || !parameters.contains("half_height"))
      reader.fail(here, "needs radius and half_height");
    return std::make_shared<CapsuleCollider>(reader.positive(parameters["radius"], here + ".radius"),
                                             reader.nonNegative(parameters["half_height"], here + ".half_height"));
  }
  if (kind == "convex") return readConvex(reader, parameters, here);
  reader.fail(path, "unknown shape '" + kind + "' (known: sphere, box, capsule, convex)");
}

// One body entry may expand to a grid of bodies ("repeat"): x varies fastest,
// then z, then y, so generated layers stack upwards in file order.
void readBody(const SceneReader& reader, const json& value, const std::string& path,
              std::vector<BodyDefinition>& bodies) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path,
                   {"name", "shape", "position", "orientation", "velocity", "angular_velocity", "mass", "static",
                    "restitution", "static_friction", "dynamic_friction", "drag", "angular_drag", "use_gravity",
                    "lock_translation", "lock_rotation", "repeat"});
  if (!value.contains("shape")) reader.fail(path, "missing key shape");
  BodyDefinition body;
  body.collider = readShape(reader, value["shape"], path + ".shape");
  const auto key = [&](const char* name) { return path + "." + name; };
  if (value.contains("name")) reader.string(value["name"], key("name"));
  if (value.contains("position")) body.position = reader.vec3(value["position"], key("position"));
  if (value.contains("orientation")) body.orientation = reader.quaternion(value["orientation"], key("orientation"));
  if (value.contains("velocity")) body.linearVelocity = reader.vec3(value["velocity"], key("velocity"));
  if (value.contains("angular_velocity"))
    body.angularVelocity = reader.vec3(value["angular_velocity"], key("angular_velocity"));
  if (value.contains("mass")) body.mass = reader.positive(value["mass"], key("mass"));
  if (value.contains("static")) body.isStatic = reader.boolean(value["static"], key("static"));
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

  body = aboutCentreOfMass(body);  // the scene states the body where its centre of mass is
  if (!value.contains("repeat")) {
    bodies.push_back(body);
    return;
  }
  const std::string here = key("repeat");
  const json& repeat = value["repeat"];
  reader.requireObject(repeat, here);
  reader.checkKeys(repeat, here, {"count", "spacing"});
  if (!repeat.contains("count") || !repeat.contains("spacing")) reader.fail(here, "needs both count and spacing");
  reader.array(repeat["count"], here + ".count", 3);
  int count[3];
  for (int axis = 0; axis < 3; ++axis)
    count[axis] = reader.positiveInteger(repeat["count"][axis], here + ".count[" + std::to_string(axis) + "]");
  if (static_cast<long long>(count[0]) * count[1] * count[2] > 1'000'000)
    reader.fail(here + ".count", "more than 1000000 bodies");
  const Vec3 spacing = reader.vec3(repeat["spacing"], here + ".spacing");
  const Vec3 origin = body.position;
  for (int y = 0; y < count[1]; ++y)
    for (int z = 0; z < count[2]; ++z)
      for (int x = 0; x < count[0]; ++x) {
        body.position = origin + Vec3(x * spacing.x(), y * spacing.y(), z * spacing.z());
        bodies.push_back(body);
      }
}

void readSolver(const SceneReader& reader, const json& value, const std::string& path, SolverSettings& solver) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"kind", "iterations", "substeps", "max_substeps"});
  if (value.contains("kind")) {
    const std::string kind = reader.string(value["kind"], path + ".kind");
    if (kind == "seed") solver.kind = SolverKind::Seed;
    else if (kind == "sequential_impulse") solver.kind = SolverKind::SequentialImpulse;
    else reader.fail(path + ".kind", "must be \"seed\" or \"sequential_impulse\", got \"" + kind + "\"");
  }
  if (value.contains("iterations")) {
    solver.velocityIterations = reader.positiveInteger(value["iterations"], path + ".iterations");
    if (solver.velocityIterations > 1000) reader.fail(path + ".iterations", "must be at most 1000");
  }
  if (value.contains("substeps")) {
    solver.substeps = reader.positiveInteger(value["substeps"], path + ".substeps");
    if (solver.substeps > 1000) reader.fail(path + ".substeps", "must be at most 1000");
  }
  if (value.contains("max_substeps")) {
    solver.maxSubsteps = reader.positiveInteger(value["max_substeps"], path + ".max_substeps");
    if (solver.maxSubsteps > 1000) reader.fail(path + ".max_substeps", "must be at most 1000");
    if (solver.maxSubsteps < solver.substeps)
      reader.fail(path + ".max_substeps",
                  "must be at least substeps (" + std::to_string(solver.substeps) + "), got " +
                      std::to_string(solver.maxSubsteps));
  }
}

SceneCamera readCamera(const SceneReader& reader, const json& value, const std::string& path) {
  reader.requireObject(value, path);
  reader.checkKeys(value, path, {"eye", "target", "fov", "orthographic"});
  SceneCamera camera;
  if (value.contains("eye")) camera.eye = reader.vec3(value["eye"], path + ".eye");
  if (value.contains("target")) camera.target = reader.vec3(value["target"], path + ".target");
  if (value.contains("fov")) camera.fovYDegrees = reader.inRange(value["fov"], path + ".fov", 1.0, 170.0);
  if (value.contains("orthographic")) camera.orthographic = reader.boolean(value["orthographic"], path + ".orthographic");
  if (camera.eye && camera.target && (*camera.eye - *camera.target).norm() < 1e-9)
    reader.fail(path, "eye and target must differ");
  return camera;
}

}  // namespace

SceneDescription parseScene(const std::string& jsonText, const std::string& sourceName) {
  const SceneReader reader(sourceName);
  json root;
  try {
    root = json::parse(jsonText);
  } catch (const json::exception& error) {  // parse errors and number overflow (1e999)
    reader.fail("", std::string("malformed JSON: ") + error.what());
  }
  reader.requireObject(root, "");
  reader.checkKeys(root, "", {"name", "description", "gravity", "dt", "steps", "bodies", "camera", "layers",
                              "allow_sleep", "broadphase", "solver"});
  SceneDescription scene;
  scene.name = std::filesystem::path(sourceName).stem().string();
  if (root.contains("name")) scene.name = reader.string(root["name"], "name");
  if (root.contains("description")) scene.description = reader.string(root["description"], "description");
  if (root.contains("gravity")) scene.world.gravity = reader.vec3(root["gravity"], "gravity");
  if (root.contains("dt")) scene.world.dt = reader.positive(root["dt"], "dt");
  if (root.contains("steps")) scene.steps = reader.positiveInteger(root["steps"], "steps");
  if (root.contains("allow_sleep")) scene.world.allowSleep = reader.boolean(root["allow_sleep"], "allow_sleep");
  if (root.contains("broadphase")) {
    const std::string kind = reader.string(root["broadphase"], "broadphase");
    if (kind == "tree") scene.world.broadPhase = BroadPhaseKind::Tree;
    else if (kind == "brute_force") scene.world.broadPhase = BroadPhaseKind::BruteForce;
    else reader.fail("broadphase", "must be \"tree\" or \"brute_force\", got \"" + kind + "\"");
  }
  if (root.contains("solver")) readSolver(reader, root["solver"], "solver", scene.world.solver);
  if (root.contains("camera")) scene.camera = readCamera(reader, root["camera"], "camera");
  if (root.contains("layers")) {
    scene.layers = reader.string(root["layers"], "layers");
    try {
      debugdraw::parseLayers(*scene.layers);
    } catch (const std::invalid_argument& error) {
      reader.fail("layers", error.what());
    }
  }
  if (!root.contains("bodies")) reader.fail("", "missing key bodies");
  const json& bodies = reader.array(root["bodies"], "bodies", 0);
  for (std::size_t i = 0; i < bodies.size(); ++i)
    readBody(reader, bodies[i], "bodies[" + std::to_string(i) + "]", scene.bodies);
  return scene;
}

SceneDescription loadSceneFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw SceneError(path + ": cannot open scene file");
  std::ostringstream text;
  text << file.rdbuf();
  if (file.bad()) throw SceneError(path + ": cannot read scene file");
  return parseScene(text.str(), path);
}

World buildWorld(const SceneDescription& scene) {
  World world(scene.world);
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    try {
      world.addBody(scene.bodies[i]);
    } catch (const std::invalid_argument& error) {
      throw SceneError(scene.name + ": bodies[" + std::to_string(i) + "]: " + error.what());
    }
  }
  return world;
}

}  // namespace physdbg
