// physdbg contacts finds its pairs with a box tree: it must give exactly the
// pairs, in the order, that testing every box against every other gives.
#include "engine/world.h"
#include "cli/overlapping_pairs.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "tests/support/visual_test_support.h"
#include "scenes/scene.h"

namespace {

using physdbg::Aabb;
using physdbg::BodyPair;
using physdbg::cli::overlappingPairs;

std::vector<BodyPair> allPairsTested(const std::vector<Aabb>& boxes) {
  std::vector<BodyPair> pairs;
  for (std::uint32_t a = 0; a < boxes.size(); ++a)
    for (std::uint32_t b = a + 1; b < boxes.size(); ++b)
      if (boxes[a].overlaps(boxes[b])) pairs.push_back({a, b});
  return pairs;
}

// Spheres, boxes and capsules at random places, a third of the boxes on a unit
// grid so that faces touch exactly, a few static, a floor under them all.
std::string randomSceneJson(unsigned seed, int bodies) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> place(-6.0, 6.0), size(0.1, 1.2);
  std::uniform_int_distribution<int> kind(0, 2), cell(-4, 4);
  std::string json = R"({"bodies": [{"shape": {"box": {"half_extents": [8, 0.5, 8]}}, "position": [0, -7, 0],
                         "static": true})";
  for (int i = 0; i < bodies; ++i) {
    const int shape = kind(random);
    const bool onGrid = shape == 1 && i % 3 == 0;
    const std::string position = onGrid ? std::to_string(cell(random)) + ", " + std::to_string(cell(random)) + ", " +
                                              std::to_string(cell(random))
                                        : std::to_string(place(random)) + ", " + std::to_string(place(random)) + ", " +
                                              std::to_string(place(random));
    const std::string r = std::to_string(size(random));
    const std::string shapes[] = {R"({"sphere": {"radius": )" + r + "}}",
                                  onGrid ? R"({"box": {"half_extents": [0.5, 0.5, 0.5]}})"
                                         : R"({"box": {"half_extents": [)" + r + ", 0.3, " + r + "]}}",
                                  R"({"capsule": {"radius": 0.2, "half_height": )" + r + "}}"};
    json += R"(, {"shape": )" + shapes[shape] + R"(, "position": [)" + position + R"(], "orientation": [1, )" +
            std::to_string(place(random) / 6) + ", 0.3, 0]" + (i % 10 == 0 ? R"(, "static": true)" : "") + "}";
  }
  return json + "]}";
}

TEST(OverlappingPairs, SameAsTestingEveryPairOnARandomScene) {
  physdbg::visualtesting::ScratchFolder folder;
  const std::string path = folder / "random.json";
  std::ofstream(path) << randomSceneJson(20240601, 600);
  const physdbg::World world = physdbg::buildWorld(physdbg::resolveScene(path));
  std::vector<Aabb> boxes;
  for (const physdbg::RigidBody& body : world.bodies()) boxes.push_back(body.collider().worldBounds(body.transform()));
  const std::vector<BodyPair> expected = allPairsTested(boxes);
  EXPECT_GT(expected.size(), 200u);  // the scene is crowded enough to say something
  EXPECT_EQ(overlappingPairs(boxes), expected);
}

TEST(OverlappingPairs, TouchingFacesCountAndEmptyInputsGiveNothing) {
  EXPECT_TRUE(overlappingPairs({}).empty());
  const Aabb unit{physdbg::Vec3(0, 0, 0), physdbg::Vec3(1, 1, 1)};
  EXPECT_TRUE(overlappingPairs({unit}).empty());
  const Aabb right{physdbg::Vec3(1, 0, 0), physdbg::Vec3(2, 1, 1)};
  const Aabb apart{physdbg::Vec3(3, 0, 0), physdbg::Vec3(4, 1, 1)};
  const std::vector<BodyPair> pairs = overlappingPairs({apart, unit, right, unit});
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{1, 2}, {1, 3}, {2, 3}}));
}

}  // namespace
