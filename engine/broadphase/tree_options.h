#pragma once
// How the dynamic AABB tree builds itself, apart from the tree so world
// settings can name it without the tree's templates.
namespace physdbg {

enum class InsertionMethod { BranchAndBound, Greedy };

struct DynamicAabbTreeOptions {
  double margin = 0.1;                // fat box = tight box + margin on every side
  double velocityPrediction = 0.0;    // fat box also extends by this factor times the displacement
  InsertionMethod insertion = InsertionMethod::BranchAndBound;
  bool rotations = true;
};

}  // namespace physdbg
