#pragma once
/// \file
/// \brief Broadphase: a static AABB tree over obstacle bounding boxes, built once.
///
/// Soundness (proof: proofs/fast-path.md#broadphase-margin): boxes are computed exactly (min
/// and max of double coordinates never round); the query box is inflated by the margin with
/// outward rounding; box-box overlap is decided by exact comparisons. An obstacle that is NOT
/// returned therefore has, on some axis k, a gap \f$g_k > m\f$ between its box and the
/// un-inflated query box, and since the Euclidean distance of two sets is at least their
/// distance along any axis, \f$\mathrm{dist}(\text{obstacle}, \text{query set}) > m\f$.
/// Obstacles whose inflated boxes merely touch ARE returned.

#include <limits>
#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// \brief Axis-aligned box \f$[lo, hi]\f$ (closed).
struct Aabb {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());

  /// \brief Exact bounding box of \p points (empty box if none).
  static Aabb of_points(const std::vector<Eigen::Vector3d>& points);
  /// \brief The box grown by \p margin >= 0 on every side, rounded outward (contains the exact
  /// Minkowski sum with \f$[-m, m]^3\f$).
  /// \throws std::invalid_argument if \p margin is negative or NaN.
  Aabb inflated(double margin) const;
  /// \brief Exact closed-box overlap test.
  bool overlaps(const Aabb& other) const {
    return (lo.array() <= other.hi.array()).all() && (other.lo.array() <= hi.array()).all();
  }
  /// \brief Exact test that \p other lies inside this box.
  bool contains(const Aabb& other) const {
    return (lo.array() <= other.lo.array()).all() && (other.hi.array() <= hi.array()).all();
  }
  void extend(const Aabb& other) {
    lo = lo.cwiseMin(other.lo);
    hi = hi.cwiseMax(other.hi);
  }
};

/// \brief Static bounding-volume hierarchy over obstacle point sets (world frame W).
///
/// Build is \f$O(n \log n)\f$; a query visits \f$O(\log n + k)\f$ nodes for \f$k\f$ hits.
class StaticObstacleIndex {
 public:
  StaticObstacleIndex() = default;
  /// \brief Builds the tree over the exact boxes of \p obstacles_W (each non-empty).
  /// \throws std::invalid_argument if an obstacle has no points.
  explicit StaticObstacleIndex(const std::vector<std::vector<Eigen::Vector3d>>& obstacles_W);
  /// \brief Builds the tree over the given boxes (box o is obstacle o's, world frame).
  explicit StaticObstacleIndex(std::vector<Aabb> boxes_W);

  /// \brief Appends to \p out (cleared first) the indices of every obstacle whose box meets
  /// `query_W.inflated(margin)`, in increasing order. Every obstacle not listed is farther
  /// than \p margin from every point of \p query_W.
  void candidates(const Aabb& query_W, double margin, std::vector<int>& out) const;
  /// \brief The answer of candidates(query_W, margin, out) taken from \p superset (sorted, and
  /// holding every obstacle whose box meets `query_W.inflated(margin)`: e.g. the candidates of
  /// a box containing that inflated box), without walking the tree.
  void candidates_among(const std::vector<int>& superset, const Aabb& query_W, double margin,
                        std::vector<int>& out) const;
  /// \brief Convenience: the box of \p points_W, then candidates().
  std::vector<int> candidates(const std::vector<Eigen::Vector3d>& points_W, double margin) const;

  int size() const { return static_cast<int>(boxes_.size()); }
  const Aabb& box(int obstacle) const { return boxes_.at(obstacle); }

 private:
  struct Node {
    Aabb box;
    int first = 0;  ///< leaf: first entry in order_; inner: index of left child
    int count = 0;  ///< leaf: number of obstacles (> 0); inner: 0, right child = first + 1
  };
  int build(int begin, int end);

  std::vector<Aabb> boxes_;
  std::vector<int> order_;  ///< obstacle indices permuted so every leaf is a contiguous range
  std::vector<Node> nodes_;
};

}  // namespace grpvss::geometry
