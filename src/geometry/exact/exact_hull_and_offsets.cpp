/// \file
/// \brief CGAL translation unit 1 of 2: exact convex hulls (ConvexPolytope::from_points) and
/// exactly verified tolerance offsets (minkowski_offset, contains_ball_sum_exactly).
///
/// Exactness model: every decision is an exact predicate on input doubles (CGAL Epick filtered
/// predicates for the hull) or exact big-float arithmetic (CGAL::Mpzf: +, -, * of doubles
/// are exact, no division is ever needed because all tests are squared). Mpzf keeps small
/// numbers on the stack (no malloc), which made it ~5x faster than Gmpzf here; sign tests are
/// first tried in interval arithmetic and fall back to Mpzf only when the interval straddles 0.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "grpvss/geometry/convex_polytope.hpp"
#include "grpvss/geometry/minkowski_offset.hpp"

namespace grpvss::geometry {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Exact = CGAL::Mpzf;  // exact for +, -, * of doubles

/// Truncation toward zero (what mpz_get_d_2exp, i.e. the former Gmpzf::to_double, returned):
/// Mpzf::to_interval brackets x between the truncated magnitude and the next double.
double truncate_to_double(const Exact& x) {
  const std::pair<double, double> iv = CGAL::to_interval(x);
  return CGAL::sign(x) == CGAL::NEGATIVE ? iv.second : iv.first;
}

Point to_point(const Eigen::Vector3d& v) { return Point(v.x(), v.y(), v.z()); }

/// Exact plane n.x <= c through three double points (n = (q-p) x (r-p), c = n.p).
struct ExactPlane {
  std::array<Exact, 3> n;
  Exact c;
};

ExactPlane exact_plane(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                       const Eigen::Vector3d& r) {
  const std::array<Exact, 3> u{Exact(q.x()) - Exact(p.x()), Exact(q.y()) - Exact(p.y()),
                               Exact(q.z()) - Exact(p.z())};
  const std::array<Exact, 3> w{Exact(r.x()) - Exact(p.x()), Exact(r.y()) - Exact(p.y()),
                               Exact(r.z()) - Exact(p.z())};
  ExactPlane plane;
  plane.n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  plane.c = plane.n[0] * Exact(p.x()) + plane.n[1] * Exact(p.y()) + plane.n[2] * Exact(p.z());
  return plane;
}

Exact exact_dot(const std::array<Exact, 3>& n, const Eigen::Vector3d& v) {
  return n[0] * Exact(v.x()) + n[1] * Exact(v.y()) + n[2] * Exact(v.z());
}

Exact exact_norm2(const std::array<Exact, 3>& n) { return n[0] * n[0] + n[1] * n[1] + n[2] * n[2]; }

/// Plane of a face of a ConvexPolytope: its first three loop vertices are never collinear.
ExactPlane face_plane(const ConvexPolytope& p, std::size_t face) {
  const auto& loop = p.faces()[face];
  const auto& v = p.vertices();
  return exact_plane(v[loop[0]], v[loop[1]], v[loop[2]]);
}

/// Throws DegenerateHullError unless the points span 3-D (exact predicates).
void require_full_dimensional(const std::vector<Point>& pts) {
  const std::size_t n = pts.size();
  if (n < 4) {
    throw DegenerateHullError("convex hull needs at least 4 points spanning 3-D, got " +
                              std::to_string(n) + " point(s)");
  }
  std::size_t i1 = 1;
  while (i1 < n && pts[i1] == pts[0]) ++i1;
  if (i1 == n) {
    throw DegenerateHullError("degenerate convex hull: all " + std::to_string(n) +
                              " points coincide");
  }
  std::size_t i2 = 1;
  while (i2 < n && CGAL::collinear(pts[0], pts[i1], pts[i2])) ++i2;
  if (i2 == n) {
    throw DegenerateHullError("degenerate convex hull: all " + std::to_string(n) +
                              " points are collinear (exact test)");
  }
  std::size_t i3 = 1;
  while (i3 < n && CGAL::orientation(pts[0], pts[i1], pts[i2], pts[i3]) == CGAL::COPLANAR) ++i3;
  if (i3 == n) {
    throw DegenerateHullError("degenerate convex hull: all " + std::to_string(n) +
                              " points are coplanar (exact test); a hull must span 3-D");
  }
}

struct UnionFind {
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
  std::vector<std::size_t> parent;
};

/// Removes loop vertices that lie (exactly) on the segment between their neighbours.
void drop_collinear(std::vector<int>& loop, const std::vector<Point>& pts) {
  bool changed = true;
  while (changed && loop.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::size_t prev = (i + loop.size() - 1) % loop.size();
      const std::size_t next = (i + 1) % loop.size();
      if (CGAL::collinear(pts[loop[prev]], pts[loop[i]], pts[loop[next]])) {
        loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
        changed = true;
        break;
      }
    }
  }
}

}  // namespace

/// Builds ConvexPolytope instances (the only friend allowed to fill one).
struct ConvexPolytopeBuilder {
  static ConvexPolytope build(const std::vector<Eigen::Vector3d>& input);
};

ConvexPolytope ConvexPolytopeBuilder::build(const std::vector<Eigen::Vector3d>& input) {
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (!input[i].allFinite()) {
      throw DegenerateHullError("convex hull point " + std::to_string(i) +
                                " has a non-finite coordinate");
    }
  }
  std::vector<Point> pts;
  pts.reserve(input.size());
  for (const auto& v : input) pts.push_back(to_point(v));
  require_full_dimensional(pts);

  // First input index of each distinct point (hull vertices are copies of input points):
  // input indices sorted by coordinates, ties by index, looked up by binary search.
  const auto key = [&input](int i) {
    return std::make_tuple(input[i].x(), input[i].y(), input[i].z());
  };
  std::vector<int> by_coords(input.size());
  std::iota(by_coords.begin(), by_coords.end(), 0);
  std::sort(by_coords.begin(), by_coords.end(), [&key](int i, int j) {
    return key(i) < key(j) || (key(i) == key(j) && i < j);
  });

  // Triangles with outward orientation, as indices into hull_points.
  // (Surface_mesh output: CGAL 5.5's point/triangle-range output of convex_hull_3 dropped a
  // vertex of the rhombicuboctahedron and left 2 points outside, so it is not used.)
  std::vector<Point> hull_points;
  std::vector<std::array<std::size_t, 3>> triangles;
  {
    Mesh mesh;
    CGAL::convex_hull_3(pts.begin(), pts.end(), mesh);
    std::vector<std::size_t> slot(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
    for (auto v : mesh.vertices()) {
      slot[v.idx()] = hull_points.size();
      hull_points.push_back(mesh.point(v));
    }
    for (auto f : mesh.faces()) {
      std::array<std::size_t, 3> tri{};
      int k = 0;
      for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
        if (k == 3) throw std::logic_error("convex_hull_3 produced a non-triangle face");
        tri[k++] = slot[v.idx()];
      }
      if (k != 3) throw std::logic_error("convex_hull_3 produced a non-triangle face");
      triangles.push_back(tri);
    }
  }

  std::vector<int> hull_to_input(hull_points.size(), -1);
  for (std::size_t v = 0; v < hull_points.size(); ++v) {
    const Point& p = hull_points[v];
    const auto wanted = std::make_tuple(p.x(), p.y(), p.z());
    const auto it = std::lower_bound(by_coords.begin(), by_coords.end(), wanted,
                                     [&key](int i, const auto& k) { return key(i) < k; });
    if (it == by_coords.end() || key(*it) != wanted) {
      throw std::logic_error("convex_hull_3 produced a new point");
    }
    hull_to_input[v] = *it;
  }

  // Directed edge u->v of triangle t at slot k (edge from corner k to corner k+1); the
  // opposite half-edge is found by binary search in the sorted list.
  struct HalfEdge {
    std::size_t u, v;
    int triangle;
    int corner;
    bool operator<(const HalfEdge& o) const { return u < o.u || (u == o.u && v < o.v); }
  };
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      half_edges.push_back({triangles[t][k], triangles[t][(k + 1) % 3], static_cast<int>(t), k});
    }
  }
  std::sort(half_edges.begin(), half_edges.end());
  const auto find_half_edge = [&half_edges](std::size_t u, std::size_t v) -> const HalfEdge& {
    const HalfEdge probe{u, v, -1, -1};
    const auto it = std::lower_bound(half_edges.begin(), half_edges.end(), probe);
    if (it == half_edges.end() || it->u != u || it->v != v) {
      throw std::logic_error("open convex hull mesh");
    }
    return *it;
  };
  // twin[3 t + k]: triangle of the opposite half-edge of (t, k).
  std::vector<int> twin_triangle(3 * triangles.size(), -1);
  for (const HalfEdge& h : half_edges) {
    twin_triangle[3 * h.triangle + h.corner] = find_half_edge(h.v, h.u).triangle;
  }

  // Merge adjacent triangles that are exactly coplanar.
  UnionFind groups(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int o = twin_triangle[3 * t + k];
      if (o < static_cast<int>(t)) continue;  // each edge once
      const auto& tri = triangles[t];
      const auto& other = triangles[o];
      // The corner of `other` not on the shared edge.
      std::size_t apex = other[0];
      for (std::size_t c : other) {
        if (c != tri[k] && c != tri[(k + 1) % 3]) apex = c;
      }
      if (CGAL::orientation(hull_points[tri[0]], hull_points[tri[1]], hull_points[tri[2]],
                            hull_points[apex]) == CGAL::COPLANAR) {
        groups.unite(t, static_cast<std::size_t>(o));
      }
    }
  }

  // Walk each group's boundary (a single CCW loop: a merged face is a convex polygon).
  std::vector<std::vector<int>> loops_input;  // input indices
  std::vector<char> visited(3 * triangles.size(), 0);
  const auto is_boundary = [&](std::size_t t, int k) {
    return groups.find(t) != groups.find(static_cast<std::size_t>(twin_triangle[3 * t + k]));
  };
  for (std::size_t t0 = 0; t0 < triangles.size(); ++t0) {
    for (int k0 = 0; k0 < 3; ++k0) {
      if (visited[3 * t0 + k0] || !is_boundary(t0, k0)) continue;
      const std::size_t group = groups.find(t0);
      std::vector<int> loop;
      std::size_t t = t0;
      int k = k0;
      do {
        if (visited[3 * t + k]) throw std::logic_error("merged hull face is not a simple polygon");
        visited[3 * t + k] = 1;
        loop.push_back(hull_to_input[triangles[t][k]]);
        // Next boundary half-edge: leave the target vertex, rotating through the group.
        int nk = (k + 1) % 3;
        while (!is_boundary(t, nk)) {
          const std::size_t u = triangles[t][nk];
          const std::size_t v = triangles[t][(nk + 1) % 3];
          const HalfEdge& opposite = find_half_edge(v, u);
          t = static_cast<std::size_t>(opposite.triangle);
          nk = (opposite.corner + 1) % 3;
          if (groups.find(t) != group) throw std::logic_error("merged hull face walk left group");
        }
        k = nk;
      } while (!(t == t0 && k == k0));
      loops_input.push_back(std::move(loop));
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!visited[3 * t + k] && is_boundary(t, k)) {
        throw std::logic_error("merged hull face has more than one boundary loop");
      }
    }
  }
  for (auto& loop : loops_input) drop_collinear(loop, pts);

  // Vertices: referenced input points, ordered by input index (deterministic).
  std::vector<int> used;
  for (const auto& loop : loops_input) used.insert(used.end(), loop.begin(), loop.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<int> input_to_vertex(input.size(), -1);
  ConvexPolytope poly;
  for (int idx : used) {
    input_to_vertex[idx] = static_cast<int>(poly.vertices_.size());
    poly.vertices_.push_back(input[idx]);
    poly.input_indices_.push_back(idx);
  }
  for (const auto& loop : loops_input) {
    std::vector<int> face;
    for (int idx : loop) face.push_back(input_to_vertex[idx]);
    poly.faces_.push_back(std::move(face));
  }

  // Edges and their two faces.
  std::map<std::pair<int, int>, int> edge_index;
  for (std::size_t f = 0; f < poly.faces_.size(); ++f) {
    const auto& loop = poly.faces_[f];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int u = loop[i];
      const int v = loop[(i + 1) % loop.size()];
      const auto key = std::make_pair(std::min(u, v), std::max(u, v));
      auto [it, inserted] = edge_index.emplace(key, static_cast<int>(poly.edges_.size()));
      if (inserted) {
        poly.edges_.push_back({key.first, key.second});
        poly.edge_faces_.push_back({-1, -1});
      }
      int& slot = poly.edge_faces_[it->second][u < v ? 0 : 1];
      if (slot != -1) throw std::logic_error("hull edge used twice in one direction");
      slot = static_cast<int>(f);
    }
  }
  for (const auto& ef : poly.edge_faces_) {
    if (ef[0] < 0 || ef[1] < 0) throw std::logic_error("hull edge with a single face");
  }

  // Display planes (rounded) and exact volume.
  Exact six_volume(0);
  for (std::size_t f = 0; f < poly.faces_.size(); ++f) {
    const auto& loop = poly.faces_[f];
    const ExactPlane plane = face_plane(poly, f);
    Eigen::Vector3d n(truncate_to_double(plane.n[0]), truncate_to_double(plane.n[1]),
                      truncate_to_double(plane.n[2]));
    n.normalize();
    double c = -std::numeric_limits<double>::infinity();
    for (int v : loop) c = std::max(c, n.dot(poly.vertices_[v]));
    poly.face_normals_.push_back(n);
    poly.face_offsets_.push_back(c);
    // Fan from loop[0]: signed volume of (0, v0, vi, vi+1) is v0 . (vi x vi+1) / 6.
    const Eigen::Vector3d& v0 = poly.vertices_[loop[0]];
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      const Eigen::Vector3d& a = poly.vertices_[loop[i]];
      const Eigen::Vector3d& b = poly.vertices_[loop[i + 1]];
      const std::array<Exact, 3> axb{Exact(a.y()) * Exact(b.z()) - Exact(a.z()) * Exact(b.y()),
                                     Exact(a.z()) * Exact(b.x()) - Exact(a.x()) * Exact(b.z()),
                                     Exact(a.x()) * Exact(b.y()) - Exact(a.y()) * Exact(b.x())};
      six_volume += exact_dot(axb, v0);
    }
  }
  if (CGAL::sign(six_volume) != CGAL::POSITIVE) {
    throw std::logic_error("exact hull volume is not positive (orientation broken)");
  }
  poly.volume_ = truncate_to_double(six_volume) / 6.0;
  return poly;
}

ConvexPolytope ConvexPolytope::from_points(const std::vector<Eigen::Vector3d>& points) {
  return ConvexPolytopeBuilder::build(points);
}

// ---------------------------------------------------------------------------------------------
// Ball-sum containment.
// proof: proofs/tolerance-offset.md#ball-containment

namespace {

void require_radius(double radius, bool allow_zero) {
  if (!std::isfinite(radius) || radius < 0.0 || (!allow_zero && radius == 0.0)) {
    throw std::invalid_argument("offset radius must be finite and " +
                                std::string(allow_zero ? ">= 0" : "> 0") + ", got " +
                                std::to_string(radius));
  }
}

/// Exact slack of one face against inner (+) B(0, r): returns true iff
/// max_h n.h + r|n| <= c, i.e. g = c - max n.h >= 0 and g^2 >= r^2 |n|^2.
bool face_contains_ball_sum_exact(const ExactPlane& plane,
                                  const std::vector<Eigen::Vector3d>& inner, double radius) {
  Exact max_h = exact_dot(plane.n, inner.front());
  for (std::size_t i = 1; i < inner.size(); ++i) {
    const Exact d = exact_dot(plane.n, inner[i]);
    if (d > max_h) max_h = d;
  }
  const Exact g = plane.c - max_h;
  if (CGAL::sign(g) == CGAL::NEGATIVE) return false;
  const Exact r(radius);
  return g * g >= r * r * exact_norm2(plane.n);
}

enum class Filtered { kTrue, kFalse, kUnknown };

/// The same test in interval arithmetic (caller holds a Protect_FPU_rounding<true> scope):
/// n = (v1 - v0) x (v2 - v0) and g = min_h n.(v0 - h) enclose the exact values, so a
/// certain sign of g and of g^2 - r^2 |n|^2 is the exact answer.
Filtered face_contains_ball_sum_interval(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                         const Eigen::Vector3d& v2,
                                         const std::vector<Eigen::Vector3d>& inner,
                                         double radius) {
  using IV = CGAL::Interval_nt<false>;
  const IV ux = IV(v1.x()) - v0.x(), uy = IV(v1.y()) - v0.y(), uz = IV(v1.z()) - v0.z();
  const IV wx = IV(v2.x()) - v0.x(), wy = IV(v2.y()) - v0.y(), wz = IV(v2.z()) - v0.z();
  const IV nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
  double g_lo = std::numeric_limits<double>::infinity();
  double g_hi = std::numeric_limits<double>::infinity();
  for (const auto& h : inner) {
    const IV g = nx * (IV(v0.x()) - h.x()) + ny * (IV(v0.y()) - h.y()) + nz * (IV(v0.z()) - h.z());
    g_lo = std::min(g_lo, g.inf());
    g_hi = std::min(g_hi, g.sup());
  }
  if (g_hi < 0.0) return Filtered::kFalse;
  if (!(g_lo >= 0.0)) return Filtered::kUnknown;
  const IV g(g_lo, g_hi);
  const IV slack = g * g - IV(radius) * IV(radius) * (nx * nx + ny * ny + nz * nz);
  if (slack.inf() >= 0.0) return Filtered::kTrue;
  if (slack.sup() < 0.0) return Filtered::kFalse;
  return Filtered::kUnknown;
}

}  // namespace

bool contains_ball_sum_exactly(const ConvexPolytope& outer,
                               const std::vector<Eigen::Vector3d>& inner, double radius) {
  require_radius(radius, /*allow_zero=*/true);
  if (inner.empty()) throw std::invalid_argument("contains_ball_sum_exactly: empty inner set");
  for (const auto& p : inner) {
    if (!p.allFinite()) throw std::invalid_argument("contains_ball_sum_exactly: non-finite point");
  }
  // Interval pass first (round-to-nearest restored before any exact fallback).
  std::vector<std::size_t> undecided;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    for (std::size_t f = 0; f < outer.faces().size(); ++f) {
      const auto& loop = outer.faces()[f];
      const auto& v = outer.vertices();
      const Filtered verdict =
          face_contains_ball_sum_interval(v[loop[0]], v[loop[1]], v[loop[2]], inner, radius);
      if (verdict == Filtered::kFalse) return false;
      if (verdict == Filtered::kUnknown) undecided.push_back(f);
    }
  }
  for (std::size_t f : undecided) {
    if (!face_contains_ball_sum_exact(face_plane(outer, f), inner, radius)) return false;
  }
  return true;
}

bool contains_ball_sum_exactly(const ConvexPolytope& outer, const ConvexPolytope& inner,
                               double radius) {
  return contains_ball_sum_exactly(outer, inner.vertices(), radius);
}

bool contains_ball_exactly(const ConvexPolytope& p, double radius) {
  return contains_ball_sum_exactly(p, std::vector<Eigen::Vector3d>{Eigen::Vector3d::Zero()},
                                   radius);
}

BallSumContainmentReport ball_sum_containment_report(const ConvexPolytope& outer,
                                                     const std::vector<Eigen::Vector3d>& inner,
                                                     double radius) {
  BallSumContainmentReport report;
  report.contained = contains_ball_sum_exactly(outer, inner, radius);
  report.worst_protrusion = -std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < outer.faces().size(); ++f) {
    const ExactPlane plane = face_plane(outer, f);
    Eigen::Vector3d n(truncate_to_double(plane.n[0]), truncate_to_double(plane.n[1]),
                      truncate_to_double(plane.n[2]));
    n.normalize();
    // Offset measured from the face's own vertex, so its rounding error is local.
    const Eigen::Vector3d& v0 = outer.vertices()[outer.faces()[f][0]];
    for (const auto& h : inner) {
      const double protrusion = n.dot(h - v0) + radius;
      if (protrusion > report.worst_protrusion) {
        report.worst_protrusion = protrusion;
        report.worst_point = h + radius * n;
        report.worst_face = static_cast<int>(f);
      }
    }
  }
  return report;
}

// ---------------------------------------------------------------------------------------------
// Offset shapes and Minkowski sums.

namespace {

std::vector<Eigen::Vector3d> offset_shape_points(double r, OffsetShape shape) {
  std::vector<Eigen::Vector3d> pts;
  if (shape == OffsetShape::kCube) {
    for (int i = 0; i < 8; ++i) {
      pts.emplace_back((i & 1) ? r : -r, (i & 2) ? r : -r, (i & 4) ? r : -r);
    }
    return pts;
  }
  // Rhombicuboctahedron: permutations of (+-t, +-t, +-r). The diagonal squares (normal
  // (1,1,0)/sqrt2) sit at distance (r + t)/sqrt2, so t >= (sqrt2 - 1) r, checked exactly;
  // the triangles sit at (r + 2t)/sqrt3 > r already.
  double t = r * (std::sqrt(2.0) - 1.0);
  const Exact er(r);
  while ((er + Exact(t)) * (er + Exact(t)) < Exact(2) * er * er) {
    t = std::nextafter(t, std::numeric_limits<double>::infinity());
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (int s = 0; s < 8; ++s) {
      Eigen::Vector3d p;
      p[axis] = (s & 1) ? r : -r;
      p[(axis + 1) % 3] = (s & 2) ? t : -t;
      p[(axis + 2) % 3] = (s & 4) ? t : -t;
      pts.push_back(p);
    }
  }
  return pts;
}

}  // namespace

ConvexPolytope offset_shape_polytope(double radius, OffsetShape shape) {
  require_radius(radius, /*allow_zero=*/false);
  ConvexPolytope p = ConvexPolytope::from_points(offset_shape_points(radius, shape));
  if (!contains_ball_exactly(p, radius)) {
    throw std::logic_error("offset shape does not contain B(0, r) (exact check)");
  }
  return p;
}

ConvexPolytope minkowski_offset(const ConvexPolytope& hull, double radius, OffsetShape shape) {
  require_radius(radius, /*allow_zero=*/false);
  double scale = 0.0;
  for (const auto& h : hull.vertices()) scale = std::max(scale, h.cwiseAbs().maxCoeff());
  const double ulp = std::nextafter(scale, std::numeric_limits<double>::infinity()) - scale;
  // proof: proofs/tolerance-offset.md#ball-containment — only the final exact check counts;
  // inflation merely gives rounding room.
  double inflate = 0.0;
  for (int attempt = 0; attempt < 12; ++attempt) {
    const double r_try = radius + inflate;
    // Every shape point is a vertex of P (same order as offset_shape_polytope's vertices), and
    // P need not be rebuilt here: the final exact check is the only acceptance criterion.
    const std::vector<Eigen::Vector3d> shape_pts = offset_shape_points(r_try, shape);
    std::vector<Eigen::Vector3d> sums;
    sums.reserve(hull.vertices().size() * shape_pts.size());
    for (const auto& h : hull.vertices()) {
      for (const auto& q : shape_pts) sums.push_back(h + q);
    }
    ConvexPolytope candidate = ConvexPolytope::from_points(sums);
    if (contains_ball_sum_exactly(candidate, hull, radius)) return candidate;
    inflate = (inflate == 0.0) ? radius * 0x1p-40 + 8.0 * ulp : 2.0 * inflate;
  }
  throw std::logic_error("minkowski_offset: no rounded candidate contains hull (+) B(0, r)");
}

}  // namespace grpvss::geometry
