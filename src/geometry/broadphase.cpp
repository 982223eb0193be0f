#include "grpvss/geometry/broadphase.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {
namespace {

constexpr int kLeafSize = 4;

}  // namespace

Aabb Aabb::of_points(const std::vector<Eigen::Vector3d>& points) {
  Aabb box;
  for (const auto& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

Aabb Aabb::inflated(double margin) const {
  using namespace rounding;
  if (!(margin >= 0.0)) throw std::invalid_argument("Aabb::inflated: margin must be >= 0");
  // proof: proofs/fast-path.md#broadphase-margin (outward rounding keeps the inflation sound)
  Aabb out;
  const UpwardRoundingScope upward;
  for (int k = 0; k < 3; ++k) {
    out.lo[k] = sub_down(lo[k], margin);
    out.hi[k] = add_up(hi[k], margin);
  }
  return out;
}

namespace {

std::vector<Aabb> boxes_of(const std::vector<std::vector<Eigen::Vector3d>>& obstacles_W) {
  std::vector<Aabb> boxes;
  boxes.reserve(obstacles_W.size());
  for (const auto& points : obstacles_W) {
    if (points.empty()) throw std::invalid_argument("StaticObstacleIndex: obstacle without points");
    boxes.push_back(Aabb::of_points(points));
  }
  return boxes;
}

}  // namespace

StaticObstacleIndex::StaticObstacleIndex(
    const std::vector<std::vector<Eigen::Vector3d>>& obstacles_W)
    : StaticObstacleIndex(boxes_of(obstacles_W)) {}

StaticObstacleIndex::StaticObstacleIndex(std::vector<Aabb> boxes_W) : boxes_(std::move(boxes_W)) {
  order_.resize(boxes_.size());
  for (int i = 0; i < static_cast<int>(order_.size()); ++i) order_[i] = i;
  if (!boxes_.empty()) {
    nodes_.reserve(2 * boxes_.size());
    build(0, static_cast<int>(boxes_.size()));
  }
}

int StaticObstacleIndex::build(int begin, int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Aabb box;
  for (int k = begin; k < end; ++k) box.extend(boxes_[order_[k]]);
  nodes_[index].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[index].first = begin;
    nodes_[index].count = end - begin;
    return index;
  }
  // Median split on the widest axis of the box centres (any split keeps queries exact).
  Aabb centres;
  for (int k = begin; k < end; ++k) {
    const Eigen::Vector3d c = 0.5 * (boxes_[order_[k]].lo + boxes_[order_[k]].hi);
    centres.lo = centres.lo.cwiseMin(c);
    centres.hi = centres.hi.cwiseMax(c);
  }
  int axis = 0;
  (centres.hi - centres.lo).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](int x, int y) {
                     return boxes_[x].lo[axis] + boxes_[x].hi[axis] <
                            boxes_[y].lo[axis] + boxes_[y].hi[axis];
                   });
  // Children are stored left = index + 1 (built next), right recorded after the left subtree.
  build(begin, middle);
  const int right = build(middle, end);
  nodes_[index].first = right;
  nodes_[index].count = 0;
  return index;
}

void StaticObstacleIndex::candidates(const Aabb& query_W, double margin,
                                     std::vector<int>& out) const {
  out.clear();
  if (nodes_.empty()) return;
  const Aabb query = query_W.inflated(margin);
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (!node.box.overlaps(query)) continue;
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k) {
        if (boxes_[order_[k]].overlaps(query)) out.push_back(order_[k]);
      }
      continue;
    }
    const int self = static_cast<int>(&node - nodes_.data());
    stack[top++] = node.first;  // right child
    stack[top++] = self + 1;    // left child
  }
  std::sort(out.begin(), out.end());
}

void StaticObstacleIndex::candidates_among(const std::vector<int>& superset, const Aabb& query_W,
                                           double margin, std::vector<int>& out) const {
  out.clear();
  const Aabb query = query_W.inflated(margin);
  for (const int o : superset) {
    if (boxes_[static_cast<std::size_t>(o)].overlaps(query)) out.push_back(o);
  }
}

std::vector<int> StaticObstacleIndex::candidates(const std::vector<Eigen::Vector3d>& points_W,
                                                 double margin) const {
  std::vector<int> out;
  candidates(Aabb::of_points(points_W), margin, out);
  return out;
}

}  // namespace grpvss::geometry
