/// \file
/// \brief Mesh input errors, welding, edge classification and connected groups.

#include "grpvss/exact/mesh_validation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/rational_vector.hpp"
#include "grpvss/exact/shape_limits.hpp"

namespace grpvss::geometry {

namespace {

std::string point_text(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

void validate_vertices(const TriangleMesh& mesh) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = mesh.vertices[v];
    if (!p.allFinite()) {
      throw InputError(mesh.source, 0, "finite vertex coordinates",
                       "vertex " + std::to_string(v) + " at " + point_text(p));
    }
    if (p.cwiseAbs().maxCoeff() > kMaxShapeCoordinate) {
      throw InputError(mesh.source, 0,
                       "|coordinates| <= 1e6 model units (is the file's unit or scale right?)",
                       "vertex " + std::to_string(v) + " at " + point_text(p));
    }
  }
}

void validate_triangles(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) {
    throw InputError(mesh.source, 0, "a mesh with at least one triangle",
                     std::to_string(mesh.vertices.size()) + " vertices and no triangles");
  }
  const int n = static_cast<int>(mesh.vertices.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int v : mesh.triangles[t]) {
      if (v < 0 || v >= n) {
        throw InputError(mesh.source, 0, "vertex indices 0.." + std::to_string(n - 1),
                         "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v));
      }
    }
  }
}

void validate_parts(const TriangleMesh& mesh) {
  if (mesh.part_names.empty()) return;
  if (mesh.triangle_part.size() != mesh.triangles.size()) {
    throw InputError(mesh.source, 0, "a part for each of the " +
                                         std::to_string(mesh.triangles.size()) + " triangles",
                     std::to_string(mesh.triangle_part.size()) + " part indices");
  }
  const int parts = static_cast<int>(mesh.part_names.size());
  for (std::size_t t = 0; t < mesh.triangle_part.size(); ++t) {
    const int part = mesh.triangle_part[t];
    if (part < 0 || part >= parts) {
      throw InputError(mesh.source, 0, "part indices 0.." + std::to_string(parts - 1),
                       "triangle " + std::to_string(t) + " in part " + std::to_string(part));
    }
  }
}

/// Welded ids: input vertices sorted by coordinates, equal coordinates share an id
/// (numbered in order of their smallest input index).
void weld(const TriangleMesh& mesh, MeshTopology& topology) {
  const auto key = [&mesh](int i) {
    const Eigen::Vector3d& p = mesh.vertices[static_cast<std::size_t>(i)];
    return std::make_tuple(p.x(), p.y(), p.z());
  };
  std::vector<int> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&key](int a, int b) { return key(a) < key(b); });
  std::vector<int> group(mesh.vertices.size(), -1);  // representative input index
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && key(order[k]) == key(order[k - 1]);
    group[order[k]] = same ? group[order[k - 1]] : order[k];
  }
  topology.weld.assign(mesh.vertices.size(), -1);
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto rep = static_cast<std::size_t>(group[v]);
    if (topology.weld[rep] < 0) {  // stable sort: rep is the smallest index of its group
      topology.weld[rep] = static_cast<int>(topology.welded_points.size());
      topology.welded_points.push_back(mesh.vertices[rep]);
      topology.first_input.push_back(static_cast<int>(rep));
    }
    topology.weld[v] = topology.weld[rep];
  }
}

bool exactly_collinear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const RationalVector ra = to_rational(a);
  const RationalVector n = cross(to_rational(b) - ra, to_rational(c) - ra);
  return sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0;
}

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
}

/// Uses of each edge by the non-degenerate triangles of a set: total, and how many run
/// low -> high id.
struct EdgeUse {
  int total = 0;
  int forward = 0;
  MeshEdgeExample example;
};

std::unordered_map<std::uint64_t, EdgeUse> edge_uses(const TriangleMesh& mesh,
                                                     const MeshTopology& topology,
                                                     const std::vector<int>& triangles) {
  std::unordered_map<std::uint64_t, EdgeUse> uses;
  for (int t : triangles) {
    // Degenerate triangles have no area: no ray crosses them, so they take no part in
    // closedness (proofs/shape-containment.md#solid).
    if (topology.degenerate[static_cast<std::size_t>(t)]) continue;
    const auto& w = topology.triangles[static_cast<std::size_t>(t)];
    const auto& input = mesh.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      const int a = w[k], b = w[(k + 1) % 3];
      EdgeUse& use = uses[edge_key(a, b)];
      if (use.total++ == 0) use.example = {t, input[k], input[(k + 1) % 3]};
      if (a < b) ++use.forward;
    }
  }
  return uses;
}

std::vector<int> all_triangles(std::size_t n) {
  std::vector<int> t(n);
  std::iota(t.begin(), t.end(), 0);
  return t;
}

struct UnionFind {
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
  std::vector<int> parent;
};

}  // namespace

void validate_mesh(const TriangleMesh& mesh) {
  validate_triangles(mesh);
  validate_vertices(mesh);
  validate_parts(mesh);
}

MeshTopology mesh_topology(const TriangleMesh& mesh) {
  MeshTopology topology;
  weld(mesh, topology);
  std::vector<char> used(topology.welded_points.size(), 0);
  std::vector<char> input_used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles) {
    std::array<int, 3> w{};
    for (int k = 0; k < 3; ++k) {
      w[k] = topology.weld[static_cast<std::size_t>(t[k])];
      input_used[static_cast<std::size_t>(t[k])] = 1;
    }
    topology.triangles.push_back(w);
    const bool repeats = w[0] == w[1] || w[1] == w[2] || w[0] == w[2];
    const bool flat = repeats || exactly_collinear(topology.welded_points[w[0]],
                                                   topology.welded_points[w[1]],
                                                   topology.welded_points[w[2]]);
    topology.degenerate.push_back(flat ? 1 : 0);
    topology.degenerate_count += flat ? 1 : 0;
  }
  topology.unused_vertices =
      static_cast<int>(std::count(input_used.begin(), input_used.end(), 0));
  for (const auto& edge_and_use : edge_uses(mesh, topology, all_triangles(mesh.triangles.size()))) {
    const auto& use = edge_and_use.second;  // a named reference: lambdas cannot capture bindings
    const auto note = [&use](int& count, std::optional<MeshEdgeExample>& first) {
      ++count;
      if (!first || use.example.triangle < first->triangle) first = use.example;
    };
    if (use.total % 2 == 1) ++topology.odd_edges;
    if (use.total == 1) note(topology.open_edges, topology.first_open_edge);
    if (use.total > 2) note(topology.nonmanifold_edges, topology.first_nonmanifold_edge);
    if (use.total == 2 && use.forward != 1) {
      note(topology.misoriented_edges, topology.first_misoriented_edge);
    }
  }
  return topology;
}

std::vector<std::vector<int>> connected_triangle_groups(const TriangleMesh& mesh,
                                                        const MeshTopology& topology,
                                                        const std::vector<int>& triangles,
                                                        bool by_part) {
  const bool split = by_part && !mesh.part_names.empty();
  // Nodes: (part, welded vertex) pairs when split, welded vertices otherwise.
  const std::size_t stride = topology.welded_points.size();
  const std::size_t parts = split ? mesh.part_names.size() : 1;
  UnionFind nodes(stride * parts);
  const auto node = [&](int t, int k) {
    const auto ti = static_cast<std::size_t>(t);
    const std::size_t part = split ? static_cast<std::size_t>(mesh.triangle_part[ti]) : 0;
    return static_cast<int>(part * stride + static_cast<std::size_t>(topology.triangles[ti][k]));
  };
  for (int t : triangles) {
    nodes.unite(node(t, 0), node(t, 1));
    nodes.unite(node(t, 0), node(t, 2));
  }
  std::vector<int> sorted = triangles;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::vector<int>> groups;
  std::unordered_map<int, std::size_t> group_of_root;
  for (int t : sorted) {
    const auto [it, inserted] = group_of_root.emplace(nodes.find(node(t, 0)), groups.size());
    if (inserted) groups.emplace_back();
    groups[it->second].push_back(t);
  }
  return groups;
}

bool group_is_closed(const TriangleMesh& mesh, const MeshTopology& topology,
                     const std::vector<int>& group) {
  for (const auto& [key, use] : edge_uses(mesh, topology, group)) {
    (void)key;
    if (use.total % 2 == 1) return false;
  }
  return true;
}

namespace {

/// For a closed, consistently oriented edge-manifold group: the first welded vertex whose
/// triangles form more than one fan (the link of the vertex is several cycles), or -1.
int first_pinched_vertex(const MeshTopology& topology, const std::vector<int>& group) {
  // Link of vertex v: for each triangle (v, b, c) the directed link edge b -> c.
  std::unordered_map<int, std::unordered_map<int, int>> link;
  for (int t : group) {
    const auto& w = topology.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) link[w[k]][w[(k + 1) % 3]] = w[(k + 2) % 3];
  }
  int worst = -1;
  for (const auto& [vertex, next] : link) {
    const int start = next.begin()->first;
    std::size_t steps = 0;
    int at = start;
    do {
      const auto it = next.find(at);
      if (it == next.end()) return vertex;  // open link: cannot happen when closed
      at = it->second;
      ++steps;
    } while (at != start && steps <= next.size());
    if (steps != next.size() && (worst < 0 || vertex < worst)) worst = vertex;
  }
  return worst;
}

std::string edge_text(const MeshEdgeExample& e) {
  return "edge " + std::to_string(e.from) + "-" + std::to_string(e.to) + " of triangle " +
         std::to_string(e.triangle);
}

}  // namespace

std::optional<std::string> oriented_manifold_problem(const TriangleMesh& mesh,
                                                     const MeshTopology& topology,
                                                     const std::vector<int>& group) {
  for (int t : group) {
    if (topology.degenerate[static_cast<std::size_t>(t)]) {
      return "triangle " + std::to_string(t) + " is degenerate (zero area)";
    }
  }
  // The bad edge seen in the lowest triangle, so the message does not depend on hashing.
  std::optional<std::pair<int, std::string>> worst;
  for (const auto& [key, use] : edge_uses(mesh, topology, group)) {
    (void)key;
    std::string why;
    if (use.total == 1) why = " bounds one triangle (open)";
    if (use.total > 2) why = " bounds " + std::to_string(use.total) + " triangles";
    if (use.total == 2 && use.forward != 1) {
      why = " is used twice in one direction (inconsistent orientation)";
    }
    if (!why.empty() && (!worst || use.example.triangle < worst->first)) {
      worst.emplace(use.example.triangle, edge_text(use.example) + why);
    }
  }
  if (worst) return worst->second;
  const int pinched = first_pinched_vertex(topology, group);
  if (pinched >= 0) {
    return "vertex " + std::to_string(topology.first_input[static_cast<std::size_t>(pinched)]) +
           " joins several separate fans of triangles (non-manifold vertex)";
  }
  return std::nullopt;
}

}  // namespace grpvss::geometry
