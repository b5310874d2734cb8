#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <string>

#include "engine/colliders/box_collider.h"
#include "engine/colliders/sphere_collider.h"
#include "engine/broadphase/dynamic_aabb_tree.h"
#include "engine/world.h"
#include "scenes/scene.h"

namespace physdbg {
namespace {

std::string errorOf(const std::string& text) {
  try {
    parseScene(text, "bad.json");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(SceneLoader, AMinimalSceneGetsTheDocumentedDefaults) {
  const SceneDescription scene = parseScene(R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}}}]})", "min.json");
  EXPECT_EQ(scene.name, "min");
  EXPECT_EQ(scene.world.gravity, Vec3(0, -9.81, 0));
  EXPECT_DOUBLE_EQ(scene.world.dt, 1.0 / 60.0);
  ASSERT_EQ(scene.bodies.size(), 1u);
  const BodyDefinition& body = scene.bodies[0];
  EXPECT_EQ(body.mass, 1.0);
  EXPECT_FALSE(body.isStatic);
  EXPECT_TRUE(body.useGravity);
  EXPECT_TRUE(body.orientation.isApprox(Quat::Identity()));
  EXPECT_EQ(body.collider->kind(), ColliderKind::Sphere);
}

TEST(SceneLoader, ReadsEveryBodyKey) {
  const SceneDescription scene = parseScene(R"({
    "gravity": [0, 0, -1], "dt": 0.01, "steps": 50, "layers": "shapes,aabbs",
    "camera": {"eye": [10, 5, 10], "target": [0, 0, 0], "fov": 40},
    "bodies": [{"shape": {"box": {"half_extents": [1, 2, 3]}}, "position": [1, 2, 3],
                "orientation": [0, 0, 1, 0], "velocity": [1, 0, 0], "angular_velocity": [0, 1, 0],
                "mass": 2.5, "static": false, "restitution": 0.4, "static_friction": 0.7,
                "dynamic_friction": 0.3, "drag": 0.1, "angular_drag": 0.2, "use_gravity": false,
                "lock_translation": [false, true, false], "lock_rotation": [true, false, false]}]})",
                                            "all.json");
  EXPECT_EQ(scene.steps, 50);
  EXPECT_EQ(scene.world.gravity, Vec3(0, 0, -1));
  ASSERT_TRUE(scene.camera.has_value());
  EXPECT_EQ(*scene.camera->eye, Vec3(10, 5, 10));
  const BodyDefinition& body = scene.bodies.at(0);
  EXPECT_EQ(static_cast<const BoxCollider&>(*body.collider).halfExtents(), Vec3(1, 2, 3));
  EXPECT_DOUBLE_EQ(body.orientation.x(), 0.0);
  EXPECT_DOUBLE_EQ(body.orientation.y(), 1.0);
  EXPECT_EQ(body.mass, 2.5);
  EXPECT_EQ(body.material.restitution, 0.4);
  EXPECT_EQ(body.material.staticFriction, 0.7);
  EXPECT_EQ(body.material.dynamicFriction, 0.3);
  EXPECT_EQ(body.linearDrag, 0.1);
  EXPECT_EQ(body.angularDrag, 0.2);
  EXPECT_FALSE(body.useGravity);
  EXPECT_TRUE(body.lockTranslation[1]);
  EXPECT_TRUE(body.lockRotation[0]);
}

TEST(SceneLoader, RepeatExpandsXThenZThenY) {
  const SceneDescription scene = parseScene(
      R"({"bodies": [{"shape": {"sphere": {"radius": 0.5}}, "position": [0, 1, 0],
                      "repeat": {"count": [2, 3, 2], "spacing": [1, 2, 3]}}]})",
      "grid.json");
  ASSERT_EQ(scene.bodies.size(), 12u);
  EXPECT_EQ(scene.bodies[1].position, Vec3(1, 1, 0));
  EXPECT_EQ(scene.bodies[2].position, Vec3(0, 1, 3));
  EXPECT_EQ(scene.bodies[4].position, Vec3(0, 3, 0));
}

struct BadScene {
  const char* what;
  const char* json;
  const char* mustMention;
};

class SceneLoaderRejects : public ::testing::TestWithParam<BadScene> {};

// Names label bodies (--labels, --highlight); copies of a repeated body are
// numbered in repeat order, and a scene without names keeps no name list.
TEST(SceneLoader, BodyNamesFollowBodiesThroughRepeat) {
  const SceneDescription scene = parseScene(R"({"bodies": [
      {"shape": {"sphere": {"radius": 1}}},
      {"shape": {"sphere": {"radius": 0.1}}, "name": "pebble", "repeat": {"count": [2, 1, 1], "spacing": [1, 0, 0]}},
      {"shape": {"box": {"half_extents": [1, 1, 1]}}, "name": "lid"}]})",
                                            "names.json");
  EXPECT_EQ(scene.bodyNames, (std::vector<std::string>{"", "pebble[0]", "pebble[1]", "lid"}));
  EXPECT_TRUE(parseScene(R"({"bodies": [{"shape": {"sphere": {"radius": 1}}}]})", "plain.json").bodyNames.empty());
}

TEST_P(SceneLoaderRejects, WithAMessageNamingFileAndKey) {
  const std::string message = errorOf(GetParam().json);
  ASSERT_FALSE(message.empty()) << "accepted: " << GetParam().json;
  EXPECT_NE(message.find("bad.json"), std::string::npos) << message;
  EXPECT_NE(message.find(GetParam().mustMention), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, SceneLoaderRejects,
    ::testing::Values(
        BadScene{"malformed", R"({"bodies": [)", "malformed JSON"},
        BadScene{"not an object", R"([1, 2])", "must be an object"},
        BadScene{"no bodies", R"({"dt": 0.1})", "missing key bodies"},
        BadScene{"unknown top key", R"({"bodies": [], "gravty": [0, 0, 0]})", "gravty"},
        BadScene{"unknown body key", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "colour": 1}]})",
                 "bodies[0].colour"},
        BadScene{"unknown shape", R"({"bodies": [{"shape": {"cone": {}}}]})", "cone"},
        BadScene{"two shapes", R"({"bodies": [{"shape": {"sphere": {"radius": 1}, "box": {}}}]})",
                 "bodies[0].shape"},
        BadScene{"missing shape", R"({"bodies": [{"position": [0, 0, 0]}]})", "missing key shape"},
        BadScene{"wrong type", R"({"bodies": [{"shape": {"sphere": {"radius": "big"}}}]})",
                 "bodies[0].shape.sphere.radius"},
        BadScene{"negative radius", R"({"bodies": [{"shape": {"sphere": {"radius": -1}}}]})", "must be positive"},
        BadScene{"zero half extent", R"({"bodies": [{"shape": {"box": {"half_extents": [1, 0, 1]}}}]})",
                 "half_extents[1]"},
        BadScene{"short vector", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "position": [0, 1]}]})",
                 "must have 3 elements"},
        BadScene{"negative mass", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "mass": -2}]})",
                 "bodies[0].mass"},
        BadScene{"zero dt", R"({"dt": 0, "bodies": []})", "dt"},
        BadScene{"negative dt", R"({"dt": -0.01, "bodies": []})", "dt"},
        BadScene{"infinite number", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "position": [1e999, 0, 0]}]})",
                 "overflow"},
        BadScene{"bool as number", R"({"gravity": [0, true, 0], "bodies": []})", "gravity[1]"},
        BadScene{"number as bool", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "static": 1}]})", "static"},
        BadScene{"zero quaternion", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "orientation": [0, 0, 0, 0]}]})",
                 "orientation"},
        BadScene{"restitution above one",
                 R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "restitution": 1.5}]})", "restitution"},
        BadScene{"bad lock", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "lock_rotation": [true]}]})",
                 "lock_rotation"},
        BadScene{"unknown layer", R"({"layers": "shapes,glitter", "bodies": []})", "glitter"},
        BadScene{"tree option on brute force",
                 R"({"broadphase": {"kind": "brute_force", "rotations": false}, "bodies": []})",
                 "broadphase.rotations"},
        BadScene{"unknown insertion", R"({"broadphase": {"insertion": "random"}, "bodies": []})",
                 "broadphase.insertion"},
        BadScene{"negative fat margin", R"({"broadphase": {"fat_margin": -1}, "bodies": []})", "broadphase.fat_margin"},
        BadScene{"unknown broad-phase key", R"({"broadphase": {"kind": "tree", "depth": 3}, "bodies": []})", "depth"},
        BadScene{"unknown combine rule", R"({"restitution_combine": "median", "bodies": []})",
                 "restitution_combine"},
        BadScene{"negative slop", R"({"solver": {"slop": -0.1}, "bodies": []})", "solver.slop"},
        BadScene{"position correction without the seed solver",
                 R"({"solver": {"position_correction": 0.5}, "bodies": []})", "seed solver only"},
        BadScene{"position correction above one",
                 R"({"solver": {"kind": "seed", "position_correction": 2}, "bodies": []})",
                 "solver.position_correction"},
        BadScene{"fractional steps", R"({"steps": 2.5, "bodies": []})", "steps"},
        BadScene{"negative threads", R"({"threads": -1, "bodies": []})", "threads"},
        BadScene{"too many threads", R"({"threads": 257, "bodies": []})", "threads"},
        BadScene{"threads not a number", R"({"threads": "all", "bodies": []})", "threads"},
        BadScene{"bad camera", R"({"camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}, "bodies": []})", "camera"},
        BadScene{"empty name", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "name": ""}]})", "bodies[0].name"},
        BadScene{"long name", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "name": ")"
                 "nnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnnn"
                 R"("}]})",
                 "1 to 64 characters"},
        BadScene{"control character in name",
                 R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "name": "a\nb"}]})", "printable ASCII"},
        BadScene{"name not a string", R"({"bodies": [{"shape": {"sphere": {"radius": 1}}, "name": 3}]})",
                 "bodies[0].name"}),
    [](const ::testing::TestParamInfo<BadScene>& info) {
      std::string name = info.param.what;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

TEST(SceneLoader, ThreadsDefaultsToEveryCoreAndIsRead) {
  const std::string bodies = R"("bodies": [{"shape": {"sphere": {"radius": 1}}}])";
  EXPECT_EQ(parseScene("{" + bodies + "}", "default.json").world.threads, 0);
  EXPECT_EQ(parseScene(R"({"threads": 3, )" + bodies + "}", "three.json").world.threads, 3);
}

TEST(SceneLoader, EveryShippedSceneFileLoads) {
  for (const auto& entry : std::filesystem::directory_iterator(PHYSDBG_SOURCE_DIR "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(buildWorld(loadSceneFile(entry.path().string())));
  }
}

TEST(SceneLoader, MissingFileIsAnErrorNamingIt) {
  EXPECT_THROW(resolveScene("/nonexistent/scene.json"), SceneError);
  try {
    resolveScene("/nonexistent/scene.json");
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/scene.json"), std::string::npos);
  }
}

TEST(BuiltinScenes, EveryBuiltinSceneBuilds) {
  for (const BuiltinScene& builtin : builtinScenes()) {
    SCOPED_TRACE(builtin.name);
    const SceneDescription scene = builtin.make();
    EXPECT_EQ(scene.name, builtin.name);
    EXPECT_FALSE(builtin.description.empty());
    World world = buildWorld(scene);
    EXPECT_EQ(world.bodyCount(), scene.bodies.size());
    world.step();
  }
}

}  // namespace
}  // namespace physdbg

namespace physdbg {
namespace {

TEST(SceneLoader, CapsuleConvexAndWorldKeys) {
  const SceneDescription scene = parseScene(R"({"allow_sleep": false, "broadphase": "brute_force", "bodies": [
      {"shape": {"capsule": {"radius": 0.25, "half_height": 0.5}}},
      {"shape": {"convex": {"points": [[0,0,0],[2,0,0],[0,2,0],[0,0,2],[2,0,0]]}}, "position": [10, 0, 0]}]})",
                                            "shapes.json");
  EXPECT_FALSE(scene.world.allowSleep);
  EXPECT_EQ(scene.world.solver.kind, SolverKind::SequentialImpulse);
  const SceneDescription seed =
      parseScene(R"({"solver": {"kind": "seed", "iterations": 3, "substeps": 8, "max_substeps": 8}, "bodies": []})",
                 "s.json");
  EXPECT_EQ(seed.world.solver.kind, SolverKind::Seed);
  EXPECT_EQ(seed.world.solver.velocityIterations, 3);
  EXPECT_EQ(seed.world.solver.substeps, 8);
  EXPECT_EQ(seed.world.solver.maxSubsteps, 8);
  EXPECT_EQ(seed.world.solver.calmSubsteps, 4);  // the defaults
  EXPECT_EQ(seed.world.solver.calmSpeed, 0.1);
  const SceneDescription calm =
      parseScene(R"({"solver": {"calm_substeps": 8, "calm_speed": 0.5}, "bodies": []})", "c.json");
  EXPECT_EQ(calm.world.solver.calmSubsteps, 8);
  EXPECT_EQ(calm.world.solver.calmSpeed, 0.5);
  EXPECT_EQ(seed.world.solver.restitutionCombine(), CombineRule::Average);  // the design's (Unity's) default
  EXPECT_EQ(scene.world.solver.restitutionCombine(), CombineRule::Maximum);
  EXPECT_EQ(scene.world.solver.frictionCombine(), CombineRule::GeometricMean);
  const SceneDescription tuned = parseScene(
      R"({"solver": {"kind": "seed", "slop": 0.01, "bounce_threshold": 0.5, "position_correction": 0.3},
          "restitution_combine": "multiply", "friction_combine": "minimum", "bodies": []})",
      "t.json");
  EXPECT_EQ(tuned.world.solver.linearSlop, 0.01);
  EXPECT_EQ(tuned.world.solver.restitutionThreshold, 0.5);
  EXPECT_EQ(tuned.world.solver.seed.positionCorrection, 0.3);
  EXPECT_EQ(tuned.world.solver.restitutionCombine(), CombineRule::Multiply);
  EXPECT_EQ(tuned.world.solver.frictionCombine(), CombineRule::Minimum);
  EXPECT_EQ(scene.world.broadPhase, BroadPhaseKind::BruteForce);
  ASSERT_EQ(scene.bodies.size(), 2u);
  EXPECT_EQ(scene.bodies[0].collider->kind(), ColliderKind::Capsule);
  EXPECT_EQ(scene.bodies[1].collider->kind(), ColliderKind::ConvexMesh);
  // The tetrahedron's centroid (0.5, 0.5, 0.5) becomes the body's position.
  EXPECT_TRUE(scene.bodies[1].position.isApprox(Vec3(10.5, 0.5, 0.5), 1e-12));
  EXPECT_TRUE(scene.bodies[1].collider->localSupport(Vec3(1, 0, 0)).isApprox(Vec3(1.5, -0.5, -0.5), 1e-12));
}

// The broad phase as an object: each switch reaches the world and its tree.
TEST(SceneLoader, BroadPhaseSwitches) {
  const SceneDescription scene = parseScene(
      R"({"broadphase": {"kind": "tree", "insertion": "greedy", "rotations": false, "fat_margin": 0.3,
                         "skip_static_pairs": false},
          "bodies": [{"shape": {"sphere": {"radius": 1}}}]})",
      "b.json");
  EXPECT_EQ(scene.world.treeInsertion, InsertionMethod::Greedy);
  EXPECT_FALSE(scene.world.treeRotations);
  EXPECT_EQ(scene.world.fatMargin, 0.3);
  EXPECT_FALSE(scene.world.skipStaticPairs);
  const World world = buildWorld(scene);
  ASSERT_NE(world.tree(), nullptr);
  EXPECT_EQ(world.tree()->options().insertion, InsertionMethod::Greedy);
  EXPECT_FALSE(world.tree()->options().rotations);
  EXPECT_EQ(world.tree()->options().margin, 0.3);
  const SceneDescription brute =
      parseScene(R"({"broadphase": {"kind": "brute_force", "fat_margin": 0}, "bodies": []})", "b.json");
  EXPECT_EQ(brute.world.broadPhase, BroadPhaseKind::BruteForce);
  EXPECT_EQ(brute.world.fatMargin, 0.0);
}

// Contact reuse is on unless the scene turns it off; a non-bool is refused
// by name.
TEST(SceneLoader, ContactReuseSwitch) {
  EXPECT_TRUE(parseScene(R"({"bodies": []})", "r.json").world.reuseContacts);
  EXPECT_FALSE(parseScene(R"({"collision": {"reuse_contacts": false}, "bodies": []})", "r.json").world.reuseContacts);
  try {
    parseScene(R"({"collision": {"reuse_contacts": 1}, "bodies": []})", "r.json");
    ADD_FAILURE() << "a number was taken for a bool";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("collision.reuse_contacts"), std::string::npos) << error.what();
  }
}

TEST(SceneLoader, RejectsBadCapsulesHullsAndWorldKeys) {
  const auto message = [](const std::string& text) {
    try {
      parseScene(text, "bad.json");
    } catch (const SceneError& error) {
      return std::string(error.what());
    }
    return std::string();
  };
  EXPECT_NE(message(R"({"bodies": [{"shape": {"capsule": {"radius": 0.5}}}]})").find("half_height"), std::string::npos);
  EXPECT_NE(message(R"({"bodies": [{"shape": {"convex": {"points": [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]}}}]})")
                .find("bodies[0].shape.convex.points"),
            std::string::npos);
  EXPECT_NE(message(R"({"bodies": [{"shape": {"convex": {"points": [[0,0,0],[1,0]]}}}]})").find("points[1]"),
            std::string::npos);
  EXPECT_NE(message(R"({"broadphase": "octree", "bodies": []})").find("broadphase"), std::string::npos);
  EXPECT_NE(message(R"({"allow_sleep": "yes", "bodies": []})").find("allow_sleep"), std::string::npos);
  EXPECT_NE(message(R"({"solver": {"kind": "pgs"}, "bodies": []})").find("solver.kind"), std::string::npos);
  EXPECT_NE(message(R"({"solver": {"iterations": 0}, "bodies": []})").find("solver.iterations"), std::string::npos);
  EXPECT_NE(message(R"({"solver": {"warm": true}, "bodies": []})").find("solver.warm"), std::string::npos);
  EXPECT_NE(message(R"({"solver": {"calm_substeps": 0}, "bodies": []})").find("solver.calm_substeps"),
            std::string::npos);
  EXPECT_NE(message(R"({"solver": {"calm_substeps": 1001}, "bodies": []})").find("solver.calm_substeps"),
            std::string::npos);
  EXPECT_NE(message(R"({"solver": {"calm_speed": -1}, "bodies": []})").find("solver.calm_speed"), std::string::npos);
  EXPECT_NE(message(R"({"solver": {"lone_substeps": 4}, "bodies": []})").find("solver.lone_substeps"),
            std::string::npos);
  EXPECT_NE(message(R"({"solver": {"substeps": 8, "max_substeps": 4}, "bodies": []})")
                .find("solver.max_substeps: must be at least substeps (8), got 4"),
            std::string::npos);
}

}  // namespace
}  // namespace physdbg
