#include "grpvss/exact/polytope_skeleton.hpp"

#include <algorithm>
#include <stdexcept>

namespace grpvss::geometry {

namespace {

// The skeleton over point_count points, polytope vertex v numbered input[v].
HullSkeleton skeleton_numbered(const ConvexPolytope& polytope, const std::vector<int>& input,
                               int point_count) {
  std::vector<int> degree(static_cast<std::size_t>(point_count), 0);
  for (const auto& edge : polytope.edges()) {
    for (const int end : edge) {
      const int point = input.at(static_cast<std::size_t>(end));
      if (point < 0 || point >= point_count) {
        throw std::invalid_argument("hull_skeleton: polytope vertex outside the point set");
      }
      ++degree[static_cast<std::size_t>(point)];
    }
  }
  HullSkeleton skeleton;
  skeleton.first.assign(static_cast<std::size_t>(point_count) + 1, 0);
  for (int i = 0; i < point_count; ++i) {
    skeleton.first[static_cast<std::size_t>(i) + 1] =
        skeleton.first[static_cast<std::size_t>(i)] + degree[static_cast<std::size_t>(i)];
  }
  skeleton.neighbours.resize(static_cast<std::size_t>(skeleton.first.back()));
  std::vector<int> filled(skeleton.first.begin(), skeleton.first.end() - 1);
  for (const auto& edge : polytope.edges()) {
    const int u = input[static_cast<std::size_t>(edge[0])];
    const int v = input[static_cast<std::size_t>(edge[1])];
    skeleton.neighbours[static_cast<std::size_t>(filled[static_cast<std::size_t>(u)]++)] = v;
    skeleton.neighbours[static_cast<std::size_t>(filled[static_cast<std::size_t>(v)]++)] = u;
  }
  // Ascending rows: the polytope's edge order may follow memory addresses, and a climb through
  // equal values must not (reports are byte-identical across runs).
  for (int i = 0; i < point_count; ++i) {
    std::sort(skeleton.neighbours.begin() + skeleton.first[static_cast<std::size_t>(i)],
              skeleton.neighbours.begin() + skeleton.first[static_cast<std::size_t>(i) + 1]);
  }
  return skeleton;
}

}  // namespace

HullSkeleton hull_skeleton(const ConvexPolytope& polytope, int point_count) {
  return skeleton_numbered(polytope, polytope.input_indices(), point_count);
}

HullSkeleton vertex_skeleton(const ConvexPolytope& polytope) {
  const int vertex_count = static_cast<int>(polytope.vertices().size());
  std::vector<int> identity(static_cast<std::size_t>(vertex_count));
  for (int v = 0; v < vertex_count; ++v) identity[static_cast<std::size_t>(v)] = v;
  return skeleton_numbered(polytope, identity, vertex_count);
}

}  // namespace grpvss::geometry
