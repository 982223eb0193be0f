#pragma once
/// \file
/// \brief A cell's obstacles, with their exact hulls and certified spheres built on first use:
/// the broadphase is built at once from the obstacles' boxes, the exact work only for the
/// obstacles a query brings near (issue 22.5). A cell of 10,000 far-away obstacles then costs
/// 10,000 boxes, not 10,000 exact hulls.
///
/// Thread-safe: every lazy entry is built once under its own std::once_flag, so the cell can be
/// shared read-only between batch threads (docs/batch.md#threads). What is built does not
/// depend on when or by whom, so outputs are the same as building all of them up front.

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/broadphase.hpp"
#include "grpvss/geometry/centroid_cull.hpp"
#include "grpvss/model/hull_points.hpp"

namespace grpvss::certify {

class ObstacleSet {
 public:
  ObstacleSet() = default;
  /// \p obstacles_W must outlive the set (the RobotCell's environment does). Each obstacle
  /// must span 3-D (the readers check it).
  explicit ObstacleSet(const std::vector<HullPoints>& obstacles_W);
  ObstacleSet(ObstacleSet&&) = default;
  ObstacleSet& operator=(ObstacleSet&&) = default;

  int size() const { return static_cast<int>(entries_count_); }
  /// Exact-hull vertices of obstacle o, world frame, in input order (vertex j is the first
  /// input point it came from): the template of its images in the link frames.
  const std::vector<Eigen::Vector3d>& vertices_W(int o) const { return built(o).vertices_W; }
  /// The exact hull of vertices_W(o) (interference points reuse it).
  const geometry::ConvexPolytope& polytope_W(int o) const { return *built(o).polytope_W; }
  /// Certified sphere about vertices_W(o).
  const geometry::CertifiedSphere& sphere_W(int o) const { return built(o).sphere_W; }
  /// The broadphase over the obstacles' boxes. The box of the input points is the box of
  /// their hull's vertices (the hull's extreme points are input points and contain them all).
  const geometry::StaticObstacleIndex& index() const { return index_; }
  /// How many obstacles' exact hulls have been built so far (for benchmarks and tests).
  int built_count() const;

 private:
  struct Entry {
    std::once_flag once;
    std::vector<Eigen::Vector3d> vertices_W;
    std::optional<geometry::ConvexPolytope> polytope_W;
    geometry::CertifiedSphere sphere_W;
    std::atomic<bool> ready{false};  ///< for built_count() only
  };
  const Entry& built(int o) const;

  const std::vector<HullPoints>* obstacles_W_ = nullptr;
  std::size_t entries_count_ = 0;
  std::unique_ptr<Entry[]> entries_;
  geometry::StaticObstacleIndex index_;
};

}  // namespace grpvss::certify
