#include "grpvss/certify/obstacle_set.hpp"

#include <atomic>
#include <stdexcept>
#include <string>

namespace grpvss::certify {
namespace {

std::vector<geometry::Aabb> boxes_of(const std::vector<HullPoints>& obstacles_W) {
  std::vector<geometry::Aabb> boxes;
  boxes.reserve(obstacles_W.size());
  for (const HullPoints& obstacle : obstacles_W) {
    if (obstacle.points.empty()) throw std::invalid_argument("ObstacleSet: obstacle without points");
    boxes.push_back(geometry::Aabb::of_points(obstacle.points));
  }
  return boxes;
}

}  // namespace

ObstacleSet::ObstacleSet(const std::vector<HullPoints>& obstacles_W)
    : obstacles_W_(&obstacles_W),
      entries_count_(obstacles_W.size()),
      entries_(std::make_unique<Entry[]>(obstacles_W.size())),
      index_(boxes_of(obstacles_W)) {}

const ObstacleSet::Entry& ObstacleSet::built(int o) const {
  if (o < 0 || static_cast<std::size_t>(o) >= entries_count_) {
    throw std::out_of_range("ObstacleSet: no obstacle " + std::to_string(o));
  }
  Entry& entry = entries_[static_cast<std::size_t>(o)];
  // Built once, read per probed pair: the flag is cheaper than call_once's check.
  if (entry.ready.load(std::memory_order_acquire)) return entry;
  std::call_once(entry.once, [&] {
    // Hulled from its own vertices, so that vertex j is input point j: the obstacle is the
    // template of its images in the link frames (CellProbe::append_points).
    const auto& points = (*obstacles_W_)[static_cast<std::size_t>(o)].points;
    entry.vertices_W = geometry::ConvexPolytope::from_points(points).vertices();
    entry.polytope_W.emplace(geometry::ConvexPolytope::from_points(entry.vertices_W));
    entry.sphere_W = geometry::certified_sphere(entry.vertices_W);
    entry.ready.store(true, std::memory_order_release);
  });
  return entry;
}

int ObstacleSet::built_count() const {
  int count = 0;
  for (std::size_t o = 0; o < entries_count_; ++o) {
    if (entries_[o].ready.load(std::memory_order_acquire)) ++count;
  }
  return count;
}

}  // namespace grpvss::certify
