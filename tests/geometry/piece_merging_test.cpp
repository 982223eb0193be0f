#include "grpvss/exact/piece_merging.hpp"

#include <gtest/gtest.h>

#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

ConvexPolytope box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  return ConvexPolytope::from_points(testing::box(lo, hi));
}

TEST(MergePieces, FaceToFaceBoxesMergeForFree) {
  const auto merged = merge_pieces({box({0, 0, 0}, {1, 1, 1}), box({1, 0, 0}, {3, 1, 1})}, 0.0);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].volume(), 3.0);
  EXPECT_EQ(merged[0].vertices().size(), 8u);
}

TEST(MergePieces, TheBudgetBoundsTheAddedVolume) {
  // An L of two boxes: their union's hull adds the triangle prism (0.5 x 2 x 2 / 2... ) =
  // hull of [0,2]x[0,1]x[0,1] u [0,1]x[0,1]x[1,2]: volume 3.5, the boxes 3: adds 0.5.
  const std::vector<ConvexPolytope> l{box({0, 0, 0}, {2, 1, 1}), box({0, 0, 1}, {1, 1, 2})};
  EXPECT_EQ(merge_pieces(l, 0.49).size(), 2u);
  const auto merged = merge_pieces(l, 0.5);
  ASSERT_EQ(merged.size(), 1u);
  EXPECT_EQ(merged[0].volume(), 3.5);
  // Pieces whose boxes do not touch are never merged, whatever the budget.
  EXPECT_EQ(merge_pieces({box({0, 0, 0}, {1, 1, 1}), box({2, 0, 0}, {3, 1, 1})}, 100.0).size(), 2u);
}

TEST(MergePieces, TheMergedPieceContainsBothInputs) {
  const ConvexPolytope a = box({0, 0, 0}, {2, 1, 1});
  const ConvexPolytope b = ConvexPolytope::from_points({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {0.5, 0.5, 1.75}});
  const auto merged = merge_pieces({a, b}, 10.0);
  ASSERT_EQ(merged.size(), 1u);
  testing::Points inputs = a.vertices();
  inputs.insert(inputs.end(), b.vertices().begin(), b.vertices().end());
  EXPECT_EQ(testing::count_points_outside_hull_exactly(merged[0].vertices(), inputs), 0);
}

}  // namespace
}  // namespace grpvss::geometry
