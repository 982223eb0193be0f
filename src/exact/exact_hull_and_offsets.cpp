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
#include <cfenv>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/minkowski_offset.hpp"
#include "grpvss/exact/polytope_skeleton.hpp"
#include "grpvss/geometry/hull_skeleton.hpp"
#include "extended_precision.hpp"

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

/// Exactly coplanar for a reason visible without the determinant (exact comparisons): all
/// four share one coordinate, or their projections onto some coordinate plane take at most
/// two values (the points lie in one plane perpendicular to it), or they form a
/// parallelogram. Axis-aligned faces of input hulls and the faces of placed templates are
/// often exactly planar in one of these ways, and only the exact path could say so otherwise.
bool visibly_coplanar(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                    const Eigen::Vector3d& r, const Eigen::Vector3d& s) {
  for (int k = 0; k < 3; ++k) {
    if (p[k] == q[k] && p[k] == r[k] && p[k] == s[k]) return true;  // in the plane x_k = p_k
  }
  for (int drop = 0; drop < 3; ++drop) {
    const int i = (drop + 1) % 3, j = (drop + 2) % 3;
    const auto same = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return a[i] == b[i] && a[j] == b[j];
    };
    // Distinct projections among p, q, r, s: at most two iff every point equals p's or the
    // first one that differs from p's.
    const Eigen::Vector3d* other = nullptr;
    bool at_most_two = true;
    for (const Eigen::Vector3d* x : {&q, &r, &s}) {
      if (same(*x, p)) continue;
      if (other == nullptr) {
        other = x;
      } else if (!same(*x, *other)) {
        at_most_two = false;
        break;
      }
    }
    if (at_most_two) return true;
  }
  // A parallelogram (a + b = c + d for a pairing, e.g. a vertical rectangle placed by a
  // rotation whose z coupling tilts both vertical edges alike) is planar. Each sum of two
  // doubles is formed in long double and used only when TwoSum shows it exact.
  if constexpr (std::numeric_limits<long double>::digits >= 64) {
    using L = long double;
    const auto exact_sum = [](double a, double b, L& sum) {
      sum = L(a) + L(b);
      const L b_virtual = sum - L(a);
      const L error = (L(a) - (sum - b_virtual)) + (L(b) - b_virtual);
      return error == 0;
    };
    const auto equal_sums = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                const Eigen::Vector3d& c, const Eigen::Vector3d& d) {
      for (int k = 0; k < 3; ++k) {
        L ab = 0, cd = 0;
        if (!exact_sum(a[k], b[k], ab) || !exact_sum(c[k], d[k], cd) || ab != cd) return false;
      }
      return true;
    };
    if (extended_precision_rounds_to_nearest() &&
        (equal_sums(p, q, r, s) || equal_sums(p, r, q, s) || equal_sums(p, s, q, r))) {
      return true;
    }
  }
  return false;
}

/// Sign of det[q - p, r - p, s - p] (positive: s on the side (q - p) x (r - p) points to),
/// decided exactly: a semi-static floating-point filter (Shewchuk's orient3d error bound
/// A, which covers the rounding of the differences too), then exact Mpzf arithmetic.
/// Cheaper than Epick's Gmpq fallback for the nearly coplanar quadruples that rounding the
/// vertices of planar faces produces.
int orientation_sign(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r,
                     const Eigen::Vector3d& s) {
  // Shewchuk's orient3d(pa, pb, pc, pd) with pd = p: the same determinant.
  const double adx = q.x() - p.x(), ady = q.y() - p.y(), adz = q.z() - p.z();
  const double bdx = r.x() - p.x(), bdy = r.y() - p.y(), bdz = r.z() - p.z();
  const double cdx = s.x() - p.x(), cdy = s.y() - p.y(), cdz = s.z() - p.z();
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::abs(bdxcdy) + std::abs(cdxbdy)) * std::abs(adz) +
                           (std::abs(cdxady) + std::abs(adxcdy)) * std::abs(bdz) +
                           (std::abs(adxbdy) + std::abs(bdxady)) * std::abs(cdz);
  constexpr double kEpsilon = 0x1p-53;
  constexpr double kErrorBoundA = (7.0 + 56.0 * kEpsilon) * kEpsilon;
  // The bound assumes no underflow: tiny permanents go to the exact path.
  if (std::isfinite(permanent) && permanent > 0x1p-900) {
    const double bound = kErrorBoundA * permanent;
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  // Exact zeros the coordinates show (SCARA placements keep many faces exactly planar) cost
  // a few compares: before the long double filter, which cannot decide them anyway.
  if (visibly_coplanar(p, q, r, s)) return 0;
  // The same filter in long double (64-bit significand: error bound A with its epsilon
  // 2^-64): rounded placements of planar faces give determinants a few double ulps from 0,
  // which 11 more bits usually decide; the rest go to Mpzf. No underflow:
  // products of three doubles stay far inside long double's exponent range.
  if constexpr (std::numeric_limits<long double>::digits >= 64) {
    using L = long double;
    const L ax = L(q.x()) - L(p.x()), ay = L(q.y()) - L(p.y()), az = L(q.z()) - L(p.z());
    const L bx = L(r.x()) - L(p.x()), by = L(r.y()) - L(p.y()), bz = L(r.z()) - L(p.z());
    const L cx = L(s.x()) - L(p.x()), cy = L(s.y()) - L(p.y()), cz = L(s.z()) - L(p.z());
    const L bxcy = bx * cy, cxby = cx * by, cxay = cx * ay, axcy = ax * cy, axby = ax * by,
            bxay = bx * ay;
    const L det_l = az * (bxcy - cxby) + bz * (cxay - axcy) + cz * (axby - bxay);
    const auto abs = [](L x) { return x < 0 ? -x : x; };
    const L permanent_l = (abs(bxcy) + abs(cxby)) * abs(az) + (abs(cxay) + abs(axcy)) * abs(bz) +
                          (abs(axby) + abs(bxay)) * abs(cz);
    constexpr L kErrorBoundALong = 8 * 0x1p-64L;  // >= (7 + 56 eps) eps, eps = 2^-64
    if (extended_precision_rounds_to_nearest()) {
      const L bound = kErrorBoundALong * permanent_l;
      if (det_l > bound) return 1;
      if (-det_l > bound) return -1;
    }
  }
  const std::array<Exact, 3> u{Exact(q.x()) - Exact(p.x()), Exact(q.y()) - Exact(p.y()),
                               Exact(q.z()) - Exact(p.z())};
  const std::array<Exact, 3> w{Exact(r.x()) - Exact(p.x()), Exact(r.y()) - Exact(p.y()),
                               Exact(r.z()) - Exact(p.z())};
  const std::array<Exact, 3> z{Exact(s.x()) - Exact(p.x()), Exact(s.y()) - Exact(p.y()),
                               Exact(s.z()) - Exact(p.z())};
  const Exact exact = u[0] * (w[1] * z[2] - w[2] * z[1]) + u[1] * (w[2] * z[0] - w[0] * z[2]) +
                      u[2] * (w[0] * z[1] - w[1] * z[0]);
  return static_cast<int>(CGAL::sign(exact));
}

/// Directed-edge table of a triangulated surface on n vertices: u->v -> half-edge id.
class HalfEdgeTable {
 public:
  explicit HalfEdgeTable(std::size_t n) : n_(n) {
    if (n_ <= kDenseLimit) dense_.assign(n_ * n_, -1);
  }
  int get(std::size_t u, std::size_t v) const {
    if (!dense_.empty()) return dense_[u * n_ + v];
    const auto it = sparse_.find(u * n_ + v);
    return it == sparse_.end() ? -1 : it->second;
  }
  void set(std::size_t u, std::size_t v, int id) {
    if (!dense_.empty()) {
      dense_[u * n_ + v] = id;
    } else if (id < 0) {
      sparse_.erase(u * n_ + v);
    } else {
      sparse_[u * n_ + v] = id;
    }
  }

 private:
  static constexpr std::size_t kDenseLimit = 128;  // 64 KiB of ints
  std::size_t n_;
  std::vector<int> dense_;
  std::unordered_map<std::size_t, int> sparse_;
};

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
void drop_collinear(std::vector<int>& loop, const std::vector<Eigen::Vector3d>& input) {
  bool changed = true;
  while (changed && loop.size() > 3) {
    changed = false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const std::size_t prev = (i + loop.size() - 1) % loop.size();
      const std::size_t next = (i + 1) % loop.size();
      if (CGAL::collinear(to_point(input[loop[prev]]), to_point(input[loop[i]]),
                          to_point(input[loop[next]]))) {
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
  using Triangle = std::array<std::size_t, 3>;
  static ConvexPolytope build(const std::vector<Eigen::Vector3d>& input);
  static std::optional<ConvexPolytope> build_from_template(const std::vector<Eigen::Vector3d>& input,
                                                  const ConvexPolytope& reference);
  /// From the outward triangles of the exact hull (corners index `corner_input`, which maps
  /// them to input indices): merged coplanar faces, edges, display planes, exact volume.
  /// `edge_signs`, when given, holds for triangle t and corner k the orientation sign of
  /// the apex of the triangle across edge (k, k+1) against t's plane (saves re-deciding).
  static ConvexPolytope finish(const std::vector<Eigen::Vector3d>& input,
                               const std::vector<int>& corner_input,
                               const std::vector<Triangle>& triangles,
                               const std::vector<signed char>* edge_signs);
  static void number_vertices(ConvexPolytope& poly, const std::vector<Eigen::Vector3d>& input,
                              std::vector<std::vector<int>> loops_input);
  static void number_edges(ConvexPolytope& poly);
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
  return finish(input, hull_to_input, triangles, nullptr);
}

namespace {

// Twin half-edges of a closed oriented mesh without sorting: the half-edge u->v filed under
// (u, v) in a HalfEdgeTable (dense for the usual small hulls); the twin of u->v is the one
// filed under (v, u). Throws when an edge has no twin or a direction is used twice (the mesh is
// not a closed 2-manifold). This runs twice for every placed hull.
class HalfEdgeTwins {
 public:
  HalfEdgeTwins(const std::vector<int>& tails, const std::vector<int>& heads,
                std::size_t vertex_count, const char* open_message, const char* twice_message) {
    HalfEdgeTable by_ends(vertex_count);
    for (std::size_t h = 0; h < tails.size(); ++h) {
      const auto u = static_cast<std::size_t>(tails[h]), v = static_cast<std::size_t>(heads[h]);
      if (by_ends.get(u, v) >= 0) throw std::logic_error(twice_message);
      by_ends.set(u, v, static_cast<int>(h));
    }
    twin_.resize(tails.size());
    for (std::size_t h = 0; h < tails.size(); ++h) {
      twin_[h] = by_ends.get(static_cast<std::size_t>(heads[h]), static_cast<std::size_t>(tails[h]));
      if (twin_[h] < 0) throw std::logic_error(open_message);
    }
  }
  int twin(std::size_t half_edge) const { return twin_[half_edge]; }

 private:
  std::vector<int> twin_;
};

}  // namespace

namespace {

using HullTriangle = std::array<std::size_t, 3>;

/// For half-edge 3 t + k (corner k to corner k+1 of triangle t): the triangle and corner of
/// its twin.
struct TriangleTwins {
  std::vector<int> triangle, corner;
};

TriangleTwins triangle_twins(const std::vector<HullTriangle>& triangles, std::size_t corners) {
  std::vector<int> tails(3 * triangles.size()), heads(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      tails[3 * t + k] = static_cast<int>(triangles[t][k]);
      heads[3 * t + k] = static_cast<int>(triangles[t][(k + 1) % 3]);
    }
  }
  const HalfEdgeTwins twins(tails, heads, corners, "open convex hull mesh", "open convex hull mesh");
  TriangleTwins result;
  result.triangle.resize(tails.size());
  result.corner.resize(tails.size());
  for (std::size_t h = 0; h < tails.size(); ++h) {
    result.triangle[h] = twins.twin(h) / 3;
    result.corner[h] = twins.twin(h) % 3;
  }
  return result;
}

/// Groups of adjacent triangles that are exactly coplanar (`edge_signs` as for finish()).
UnionFind coplanar_groups(const std::vector<Eigen::Vector3d>& input,
                          const std::vector<int>& hull_to_input,
                          const std::vector<HullTriangle>& triangles, const TriangleTwins& twins,
                          const std::vector<signed char>* edge_signs) {
  const auto corner_point = [&](std::size_t corner) -> const Eigen::Vector3d& {
    return input[static_cast<std::size_t>(hull_to_input[corner])];
  };
  UnionFind groups(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int o = twins.triangle[3 * t + k];
      if (o < static_cast<int>(t)) continue;  // each edge once
      const auto& tri = triangles[t];
      const auto& other = triangles[o];
      // The corner of `other` not on the shared edge.
      std::size_t apex = other[0];
      for (std::size_t c : other) {
        if (c != tri[k] && c != tri[(k + 1) % 3]) apex = c;
      }
      const int side = edge_signs != nullptr
                           ? (*edge_signs)[3 * t + k]
                           : orientation_sign(corner_point(tri[0]), corner_point(tri[1]),
                                              corner_point(tri[2]), corner_point(apex));
      if (side == 0) groups.unite(t, static_cast<std::size_t>(o));
    }
  }
  return groups;
}

/// Each group's boundary, walked as a single CCW loop of input indices (a merged face is a
/// convex polygon).
std::vector<std::vector<int>> group_boundaries(const std::vector<int>& hull_to_input,
                                               const std::vector<HullTriangle>& triangles,
                                               const TriangleTwins& twins, UnionFind& groups) {
  std::vector<std::vector<int>> loops;
  std::vector<char> visited(3 * triangles.size(), 0);
  const auto is_boundary = [&](std::size_t t, int k) {
    return groups.find(t) != groups.find(static_cast<std::size_t>(twins.triangle[3 * t + k]));
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
          const int opposite_corner = twins.corner[3 * t + nk];
          t = static_cast<std::size_t>(twins.triangle[3 * t + nk]);
          nk = (opposite_corner + 1) % 3;
          if (groups.find(t) != group) throw std::logic_error("merged hull face walk left group");
        }
        k = nk;
      } while (!(t == t0 && k == k0));
      loops.push_back(std::move(loop));
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (!visited[3 * t + k] && is_boundary(t, k)) {
        throw std::logic_error("merged hull face has more than one boundary loop");
      }
    }
  }
  return loops;
}

/// Faces: merged groups of exactly coplanar adjacent triangles, as loops of input indices. A
/// template hull whose edges are all strictly convex (every sign < 0) has only triangles: each
/// is its own face.
std::vector<std::vector<int>> merged_face_loops(const std::vector<Eigen::Vector3d>& input,
                                                const std::vector<int>& hull_to_input,
                                                const std::vector<HullTriangle>& triangles,
                                                const std::vector<signed char>* edge_signs) {
  const bool only_triangles =
      edge_signs != nullptr &&
      std::none_of(edge_signs->begin(), edge_signs->end(), [](signed char s) { return s == 0; });
  if (only_triangles) {
    std::vector<std::vector<int>> loops;
    loops.reserve(triangles.size());
    for (const HullTriangle& t : triangles) {
      loops.push_back({hull_to_input[t[0]], hull_to_input[t[1]], hull_to_input[t[2]]});
    }
    return loops;
  }
  const TriangleTwins twins = triangle_twins(triangles, hull_to_input.size());
  UnionFind groups = coplanar_groups(input, hull_to_input, triangles, twins, edge_signs);
  std::vector<std::vector<int>> loops = group_boundaries(hull_to_input, triangles, twins, groups);
  for (auto& loop : loops) drop_collinear(loop, input);
  return loops;
}

}  // namespace

// Vertices: referenced input points, ordered by input index (deterministic). Marks instead of
// a sort, and the loops renumbered in place: this runs for every placed hull.
void ConvexPolytopeBuilder::number_vertices(ConvexPolytope& poly,
                                            const std::vector<Eigen::Vector3d>& input,
                                            std::vector<std::vector<int>> loops_input) {
  std::vector<int> input_to_vertex(input.size(), -1);
  for (const auto& loop : loops_input) {
    for (int idx : loop) input_to_vertex[static_cast<std::size_t>(idx)] = 0;
  }
  for (std::size_t idx = 0; idx < input.size(); ++idx) {
    if (input_to_vertex[idx] < 0) continue;
    input_to_vertex[idx] = static_cast<int>(poly.vertices_.size());
    poly.vertices_.push_back(input[idx]);
    poly.input_indices_.push_back(static_cast<int>(idx));
  }
  for (auto& loop : loops_input) {
    for (int& idx : loop) idx = input_to_vertex[static_cast<std::size_t>(idx)];
  }
  poly.faces_ = std::move(loops_input);
}

// Edges and their two faces, numbered in order of first appearance along the face loops (twins
// from compressed rows, no sort and no map: this runs for every placed hull).
void ConvexPolytopeBuilder::number_edges(ConvexPolytope& poly) {
  std::size_t corner_count = 0;
  for (const auto& loop : poly.faces_) corner_count += loop.size();
  std::vector<int> tails, heads, face_of;
  tails.reserve(corner_count);
  heads.reserve(corner_count);
  face_of.reserve(corner_count);
  poly.edges_.reserve(corner_count / 2);
  poly.edge_faces_.reserve(corner_count / 2);
  for (std::size_t f = 0; f < poly.faces_.size(); ++f) {
    const auto& loop = poly.faces_[f];
    for (std::size_t i = 0; i < loop.size(); ++i) {
      tails.push_back(loop[i]);
      heads.push_back(loop[(i + 1) % loop.size()]);
      face_of.push_back(static_cast<int>(f));
    }
  }
  const HalfEdgeTwins twins(tails, heads, poly.vertices_.size(), "hull edge with a single face",
                            "hull edge used twice in one direction");
  std::vector<char> numbered(tails.size(), 0);
  for (std::size_t h = 0; h < tails.size(); ++h) {
    if (numbered[h]) continue;
    const std::size_t g = static_cast<std::size_t>(twins.twin(h));
    numbered[h] = numbered[g] = 1;
    const bool h_forward = tails[h] < heads[h];  // low -> high
    poly.edges_.push_back({std::min(tails[h], heads[h]), std::max(tails[h], heads[h])});
    poly.edge_faces_.push_back(h_forward ? std::array<int, 2>{face_of[h], face_of[g]}
                                         : std::array<int, 2>{face_of[g], face_of[h]});
  }
}

ConvexPolytope ConvexPolytopeBuilder::finish(const std::vector<Eigen::Vector3d>& input,
                                             const std::vector<int>& hull_to_input,
                                             const std::vector<Triangle>& triangles,
                                             const std::vector<signed char>* edge_signs) {
  ConvexPolytope poly;
  number_vertices(poly, input, merged_face_loops(input, hull_to_input, triangles, edge_signs));
  number_edges(poly);
  // The template path's callers (placed hulls in the verifier) never read the display
  // planes or the volume; they are computed on first use there.
  if (edge_signs == nullptr) poly.compute_measures();
  return poly;
}

void ConvexPolytope::compute_measures() const {
  const ConvexPolytope& poly = *this;  // fills the mutable cache only
  poly.face_normals_.clear();
  poly.face_offsets_.clear();
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
  measures_ready_ = true;
}

ConvexPolytope ConvexPolytope::from_points(const std::vector<Eigen::Vector3d>& points) {
  return ConvexPolytopeBuilder::build(points);
}

namespace {

// Hypothesis (H0): the candidate surface uses every input point, each exactly once, as a vertex.
bool template_fits(const std::vector<Eigen::Vector3d>& input, const ConvexPolytope& reference) {
  const std::size_t n = input.size();
  if (reference.vertices().size() != n || n < 4) return false;
  std::vector<char> seen(n, 0);
  for (int i : reference.input_indices()) {
    if (i < 0 || static_cast<std::size_t>(i) >= n || seen[i]) return false;
    seen[i] = 1;
  }
  return std::all_of(input.begin(), input.end(), [](const auto& p) { return p.allFinite(); });
}

/// The reference's faces, fan-triangulated (corner indices).
std::vector<HullTriangle> fan_triangles(const ConvexPolytope& reference) {
  std::vector<HullTriangle> triangles;
  triangles.reserve(2 * reference.vertices().size());
  for (const auto& loop : reference.faces()) {
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
      triangles.push_back({static_cast<std::size_t>(loop[0]), static_cast<std::size_t>(loop[i]),
                           static_cast<std::size_t>(loop[i + 1])});
    }
  }
  return triangles;
}

/// Placement rounding bends planar faces and can bend nearly flat edges the other way: every
/// reflex edge is flipped (Lawson) until no edge is reflex (H1), decided exactly. Returns the
/// orientation sign of every half-edge's far apex (finish()'s `edge_signs`), or nullopt when
/// the flips do not end in a convex surface.
class ReflexEdgeFlips {
 public:
  ReflexEdgeFlips(const std::vector<Eigen::Vector3d>& input, const std::vector<int>& corner_input,
                  std::vector<HullTriangle>& triangles)
      : input_(input),
        corner_input_(corner_input),
        triangles_(triangles),
        half_edge_(input.size()),
        edge_signs_(3 * triangles.size(), 0),
        decided_(3 * triangles.size(), 0) {}

  std::optional<std::vector<signed char>> run();

 private:
  const Eigen::Vector3d& at(std::size_t corner) const {
    return input_[static_cast<std::size_t>(corner_input_[corner])];
  }
  void link(std::size_t t, bool present);
  void queue_every_edge();
  /// Decides edge u-v: convex or flat (recorded), or reflex (flipped). False when a flip is
  /// impossible or the flips do not end.
  bool settle(std::size_t u, std::size_t v);

  const std::vector<Eigen::Vector3d>& input_;
  const std::vector<int>& corner_input_;
  std::vector<HullTriangle>& triangles_;
  /// half_edge(u, v) = 3 t + k for the directed edge u->v at corner k of triangle t, -1 if
  /// absent: a dense table for the usual small hulls, a hash map beyond.
  HalfEdgeTable half_edge_;
  std::vector<signed char> edge_signs_;
  std::vector<char> decided_;
  std::vector<std::array<std::size_t, 2>> pending_;
  std::size_t flips_ = 0;
};

void ReflexEdgeFlips::link(std::size_t t, bool present) {
  for (int k = 0; k < 3; ++k) {
    half_edge_.set(triangles_[t][k], triangles_[t][(k + 1) % 3],
                   present ? static_cast<int>(3 * t + k) : -1);
    decided_[3 * t + k] = 0;
  }
}

void ReflexEdgeFlips::queue_every_edge() {
  for (std::size_t t = 0; t < triangles_.size(); ++t) link(t, true);
  for (const HullTriangle& t : triangles_) {
    for (int k = 0; k < 3; ++k) {
      if (half_edge_.get(t[(k + 1) % 3], t[k]) < 0) {
        throw std::logic_error("placed hull template is not a closed surface");
      }
      if (t[k] < t[(k + 1) % 3]) pending_.push_back({t[k], t[(k + 1) % 3]});
    }
  }
}

bool ReflexEdgeFlips::settle(std::size_t u, std::size_t v) {
  const int near = half_edge_.get(u, v);
  const int far = half_edge_.get(v, u);
  if (near < 0 || far < 0) return true;  // flipped away meanwhile
  const std::size_t t = static_cast<std::size_t>(near) / 3, t2 = static_cast<std::size_t>(far) / 3;
  const std::size_t c = triangles_[t][(near % 3 + 2) % 3];
  const std::size_t d = triangles_[t2][(far % 3 + 2) % 3];
  const int side = orientation_sign(at(triangles_[t][0]), at(triangles_[t][1]),
                                    at(triangles_[t][2]), at(d));
  if (side <= 0) {
    edge_signs_[near] = edge_signs_[far] = static_cast<signed char>(side);
    decided_[near] = decided_[far] = 1;
    return true;
  }
  // Reflex edge u-v: replace triangles (u, v, c), (v, u, d) by (u, d, c), (d, v, c).
  if (half_edge_.get(c, d) >= 0 || ++flips_ > 4 * triangles_.size()) return false;
  link(t, false);
  link(t2, false);
  triangles_[t] = {u, d, c};
  triangles_[t2] = {d, v, c};
  link(t, true);
  link(t2, true);
  // The new diagonal's sign is exactly -side (same four points, two of them swapped).
  const int dc = half_edge_.get(d, c), cd = half_edge_.get(c, d);
  edge_signs_[dc] = edge_signs_[cd] = static_cast<signed char>(-side);
  decided_[dc] = decided_[cd] = 1;
  for (const auto& [a, b] : {std::array<std::size_t, 2>{u, d}, {d, v}, {v, c}, {c, u}}) {
    pending_.push_back({std::min(a, b), std::max(a, b)});
  }
  return true;
}

std::optional<std::vector<signed char>> ReflexEdgeFlips::run() {
  queue_every_edge();
  while (!pending_.empty()) {
    const auto [u, v] = pending_.back();
    pending_.pop_back();
    if (!settle(u, v)) return std::nullopt;
  }
  if (std::find(decided_.begin(), decided_.end(), 0) != decided_.end()) {
    throw std::logic_error("placed hull: an edge was left undecided");
  }
  return std::move(edge_signs_);
}

/// (H2) a centre strictly below every triangle's plane, and (H3) the ray from the centre
/// through a point inside triangle 0's cone meets no other triangle's closed cone: the radial
/// projection has degree one.
bool star_shaped_once_around(const std::vector<Eigen::Vector3d>& input,
                             const std::vector<int>& corner_input,
                             const std::vector<HullTriangle>& triangles) {
  const auto at = [&](std::size_t corner) -> const Eigen::Vector3d& {
    return input[static_cast<std::size_t>(corner_input[corner])];
  };
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : input) centre += p;
  centre /= static_cast<double>(input.size());
  for (const HullTriangle& t : triangles) {
    if (orientation_sign(at(t[0]), at(t[1]), at(t[2]), centre) >= 0) return false;
  }
  const HullTriangle& first = triangles.front();
  const Eigen::Vector3d target = (at(first[0]) + at(first[1]) + at(first[2])) / 3.0;
  // The third corner c of triangle (a, b, c) is always on the positive side of
  // plane(centre, a, b): det[a-o, b-o, c-o] = -orient(a, b, c, o) > 0 by (H2), so the cone
  // test needs only the target's sides (proofs/placed-hull.md#implementation).
  const auto side = [&](const HullTriangle& t, int k) {
    return orientation_sign(centre, at(t[k]), at(t[(k + 1) % 3]), target);
  };
  if (side(first, 0) <= 0 || side(first, 1) <= 0 || side(first, 2) <= 0) return false;
  for (std::size_t t = 1; t < triangles.size(); ++t) {
    const HullTriangle& other = triangles[t];
    if (side(other, 0) >= 0 && side(other, 1) >= 0 && side(other, 2) >= 0) return false;
  }
  return true;
}

}  // namespace

// proof: proofs/placed-hull.md#lemma-placed-hull (every check is one of its hypotheses)
std::optional<ConvexPolytope> ConvexPolytopeBuilder::build_from_template(
    const std::vector<Eigen::Vector3d>& input, const ConvexPolytope& reference) {
  if (!template_fits(input, reference)) return std::nullopt;                       // (H0)
  std::vector<Triangle> triangles = fan_triangles(reference);
  const auto edge_signs = ReflexEdgeFlips(input, reference.input_indices(), triangles).run();
  if (!edge_signs) return std::nullopt;                                            // (H1)
  if (!star_shaped_once_around(input, reference.input_indices(), triangles)) {     // (H2), (H3)
    return std::nullopt;
  }
  return finish(input, reference.input_indices(), triangles, &*edge_signs);
}

std::optional<ConvexPolytope> ConvexPolytope::from_template(
    const std::vector<Eigen::Vector3d>& points, const ConvexPolytope& reference) {
  return ConvexPolytopeBuilder::build_from_template(points, reference);
}

ConvexPolytope ConvexPolytope::from_points_like(const std::vector<Eigen::Vector3d>& points,
                                                const ConvexPolytope& reference) {
  if (auto placed = from_template(points, reference)) return *std::move(placed);
  return from_points(points);
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
using IV = CGAL::Interval_nt<false>;

/// An enclosure of the exact face normal n = (v1 - v0) x (v2 - v0) (caller holds a
/// Protect_FPU_rounding<true> scope).
std::array<IV, 3> face_normal_interval(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                       const Eigen::Vector3d& v2) {
  const IV ux = IV(v1.x()) - v0.x(), uy = IV(v1.y()) - v0.y(), uz = IV(v1.z()) - v0.z();
  const IV wx = IV(v2.x()) - v0.x(), wy = IV(v2.y()) - v0.y(), wz = IV(v2.z()) - v0.z();
  return {uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx};
}

/// An enclosure of n.(a - b) for the exact n inside `n` (caller holds the rounding scope).
IV dot_difference_interval(const std::array<IV, 3>& n, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b) {
  return n[0] * (IV(a.x()) - b.x()) + n[1] * (IV(a.y()) - b.y()) + n[2] * (IV(a.z()) - b.z());
}

/// The verdict from an enclosure [g_lo, g_hi] of g = c - max n.h: certain signs of g and of
/// g^2 - r^2 |n|^2 are the exact answer.
Filtered ball_sum_verdict(double g_lo, double g_hi, const std::array<IV, 3>& n, double radius) {
  if (g_hi < 0.0) return Filtered::kFalse;
  if (!(g_lo >= 0.0)) return Filtered::kUnknown;
  const IV g(g_lo, g_hi);
  const IV slack = g * g - IV(radius) * IV(radius) * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (slack.inf() >= 0.0) return Filtered::kTrue;
  if (slack.sup() < 0.0) return Filtered::kFalse;
  return Filtered::kUnknown;
}

Filtered face_contains_ball_sum_interval(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                         const Eigen::Vector3d& v2,
                                         const std::vector<Eigen::Vector3d>& inner,
                                         double radius) {
  const std::array<IV, 3> n = face_normal_interval(v0, v1, v2);
  double g_lo = std::numeric_limits<double>::infinity();
  double g_hi = std::numeric_limits<double>::infinity();
  for (const auto& h : inner) {
    const IV g = dot_difference_interval(n, v0, h);
    g_lo = std::min(g_lo, g.inf());
    g_hi = std::min(g_hi, g.sup());
  }
  return ball_sum_verdict(g_lo, g_hi, n, radius);
}

/// An enclosure [lo, hi] of g = min_h n.(v0 - h) over `inner` (the exact hull's vertices,
/// `skeleton` its edge graph) for the exact n inside `n`, from a set T of vertices only: the
/// climb's end (from `start`, then updated to it) and the vertices connected to it whose
/// values tie with it. T is proven to hold a minimiser when every neighbour y outside T has
/// g_y >= every g_t (t in T) certainly; nullopt where it does not (the caller scans).
/// proof: proofs/offset-containment.md#lemma-climbed-support
std::optional<std::pair<double, double>> climbed_gap_enclosure(
    const std::array<IV, 3>& n, const Eigen::Vector3d& v0,
    const std::vector<Eigen::Vector3d>& inner, const HullSkeleton& skeleton, int& start) {
  const Eigen::Vector3d direction(CGAL::to_double(n[0]), CGAL::to_double(n[1]),
                                  CGAL::to_double(n[2]));
  const int x = climb_support_index(inner, skeleton, start, direction);
  start = x;
  const auto point = [&](int i) -> const Eigen::Vector3d& { return inner[static_cast<std::size_t>(i)]; };
  const double tie = 1e-12 * direction.cwiseAbs().sum() *
                     (point(x).cwiseAbs().maxCoeff() + v0.cwiseAbs().maxCoeff() + 1e-300);
  TiedSupportSet tied;
  if (!tied.gather(inner, skeleton, direction, x, tie)) return std::nullopt;
  double lo = std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  double largest_hi = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < tied.size(); ++k) {
    const IV g = dot_difference_interval(n, v0, point(tied.member(k)));
    lo = std::min(lo, g.inf());
    hi = std::min(hi, g.sup());
    largest_hi = std::max(largest_hi, g.sup());
  }
  const bool proven = tied.every_outside_neighbour(skeleton, [&](int y) {
    return dot_difference_interval(n, v0, point(y)).inf() >= largest_hi;
  });
  if (!proven) return std::nullopt;
  return std::pair<double, double>(lo, hi);
}

/// face_contains_ball_sum_interval() with min g taken over the climbed, proven set T instead
/// of over every inner point; the scan where T is not proven. `start`: the climb's warm start.
/// `climbed` counts the faces T decided (not scanned).
Filtered face_contains_ball_sum_climbed(const Eigen::Vector3d& v0, const Eigen::Vector3d& v1,
                                        const Eigen::Vector3d& v2,
                                        const std::vector<Eigen::Vector3d>& inner,
                                        const HullSkeleton& skeleton, double radius, int& start,
                                        int& climbed) {
  const std::array<IV, 3> n = face_normal_interval(v0, v1, v2);
  const auto gap = climbed_gap_enclosure(n, v0, inner, skeleton, start);
  if (!gap) return face_contains_ball_sum_interval(v0, v1, v2, inner, radius);
  ++climbed;
  return ball_sum_verdict(gap->first, gap->second, n, radius);
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

// proof: proofs/offset-containment.md#lemma-climbed-support (max n.h at a proven vertex)
bool contains_ball_sum_by_climbing(const ConvexPolytope& outer, const ConvexPolytope& inner,
                                   double radius, int* faces_climbed) {
  require_radius(radius, /*allow_zero=*/true);
  const std::vector<Eigen::Vector3d>& inner_vertices = inner.vertices();
  const HullSkeleton skeleton = vertex_skeleton(inner);
  std::vector<std::size_t> undecided;
  int climbed = 0;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    int start = 0;  // neighbouring faces have close normals: each climb starts at the last end
    for (std::size_t f = 0; f < outer.faces().size(); ++f) {
      const auto& loop = outer.faces()[f];
      const auto& v = outer.vertices();
      const Filtered verdict = face_contains_ball_sum_climbed(v[loop[0]], v[loop[1]], v[loop[2]],
                                                              inner_vertices, skeleton, radius,
                                                              start, climbed);
      if (faces_climbed != nullptr) *faces_climbed = climbed;
      if (verdict == Filtered::kFalse) return false;
      if (verdict == Filtered::kUnknown) undecided.push_back(f);
    }
  }
  for (std::size_t f : undecided) {
    if (!face_contains_ball_sum_exact(face_plane(outer, f), inner_vertices, radius)) return false;
  }
  return true;
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
    if (contains_ball_sum_by_climbing(candidate, hull, radius)) return candidate;
    inflate = (inflate == 0.0) ? radius * 0x1p-40 + 8.0 * ulp : 2.0 * inflate;
  }
  throw std::logic_error("minkowski_offset: no rounded candidate contains hull (+) B(0, r)");
}

}  // namespace grpvss::geometry
