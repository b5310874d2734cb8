// One combine function for both solvers: each rule on a pair, and the
// defaults each solver kind resolves to.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/contacts/material_combine.h"
#include "engine/solver/solver_settings.h"

namespace physdbg {
namespace {

TEST(MaterialCombine, EachRuleOnOnePair) {
  EXPECT_EQ(combine(CombineRule::Average, 0.2, 0.6), 0.4);
  EXPECT_EQ(combine(CombineRule::Minimum, 0.2, 0.6), 0.2);
  EXPECT_EQ(combine(CombineRule::Maximum, 0.2, 0.6), 0.6);
  EXPECT_DOUBLE_EQ(combine(CombineRule::Multiply, 0.2, 0.6), 0.12);
  EXPECT_DOUBLE_EQ(combine(CombineRule::GeometricMean, 0.2, 0.6), std::sqrt(0.12));
  // A frictionless surface makes every pair on it frictionless under the
  // multiplicative rules, and only there.
  EXPECT_EQ(combine(CombineRule::GeometricMean, 0.0, 0.9), 0.0);
  EXPECT_EQ(combine(CombineRule::Average, 0.0, 0.9), 0.45);
}

TEST(MaterialCombine, FrictionRuleAppliesToStaticAndDynamicAlike) {
  const Material a{0.0, 0.8, 0.4}, b{1.0, 0.2, 0.1};
  const CombinedMaterial pair = combineMaterials(a, b, CombineRule::Average, CombineRule::Minimum);
  EXPECT_EQ(pair.restitution, 0.5);
  EXPECT_EQ(pair.staticFriction, 0.2);
  EXPECT_EQ(pair.dynamicFriction, 0.1);
}

TEST(MaterialCombine, EachSolverHasItsDefaultsAndAnExplicitRuleWins) {
  SolverSettings settings;
  EXPECT_EQ(settings.restitutionCombine(), CombineRule::Maximum);
  EXPECT_EQ(settings.frictionCombine(), CombineRule::GeometricMean);
  settings.kind = SolverKind::Seed;
  EXPECT_EQ(settings.restitutionCombine(), CombineRule::Average);
  EXPECT_EQ(settings.frictionCombine(), CombineRule::Average);
  settings.combine.restitution = CombineRule::Multiply;
  EXPECT_EQ(settings.restitutionCombine(), CombineRule::Multiply);
}

}  // namespace
}  // namespace physdbg
