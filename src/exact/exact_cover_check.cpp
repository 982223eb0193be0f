/// \file
/// \brief Exact verification of a convex decomposition against the surface it decomposes
/// (proofs/shape-containment.md#lemma-exact-cover), and the outward rounding of its pieces
/// (#lemma-outward-rounding). GMP rationals only; no CGAL, no floating-point decision.

#include "grpvss/exact/exact_cover_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "grpvss/exact/rational_vector.hpp"

namespace grpvss::geometry {

namespace {

// ---- planar covering in exact arithmetic --------------------------------------------------

using Point2 = std::array<mpq_class, 2>;
using Polygon2 = std::vector<Point2>;  // convex, counter-clockwise

mpq_class twice_area(const Polygon2& p) {
  mpq_class sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& a = p[i];
    const Point2& b = p[(i + 1) % p.size()];
    sum += a[0] * b[1] - a[1] * b[0];
  }
  return sum;
}

bool has_area(const Polygon2& p) { return p.size() >= 3 && sgn(twice_area(p)) != 0; }

/// (b - a) x (p - a): positive when p is left of the directed line a -> b.
mpq_class side(const Point2& a, const Point2& b, const Point2& p) {
  return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
}

/// The part of convex `poly` in the closed half-plane left of a -> b (keep = +1) or right
/// of it (keep = -1).
Polygon2 clip(const Polygon2& poly, const Point2& a, const Point2& b, int keep) {
  Polygon2 out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point2& p = poly[i];
    const Point2& q = poly[(i + 1) % poly.size()];
    const mpq_class sp = keep * side(a, b, p);
    const mpq_class sq = keep * side(a, b, q);
    if (sgn(sp) >= 0) out.push_back(p);
    if ((sgn(sp) > 0 && sgn(sq) < 0) || (sgn(sp) < 0 && sgn(sq) > 0)) {
      const mpq_class t = sp / (sp - sq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

/// Convex pieces of positive area whose union contains r \ g up to zero area (g convex,
/// CCW): the part outside edge j of g and inside edges 0..j-1, for each j.
std::vector<Polygon2> subtract(const Polygon2& r, const Polygon2& g) {
  std::vector<Polygon2> out;
  Polygon2 rest = r;
  for (std::size_t j = 0; j < g.size(); ++j) {
    const Point2& a = g[j];
    const Point2& b = g[(j + 1) % g.size()];
    Polygon2 outside = clip(rest, a, b, -1);
    if (has_area(outside)) out.push_back(std::move(outside));
    rest = clip(rest, a, b, +1);
    if (!has_area(rest)) break;
  }
  return out;
}

struct Box2 {
  Point2 lo, hi;
};

Box2 bounds(const Polygon2& p) {
  Box2 b{p.front(), p.front()};
  for (const Point2& q : p) {
    for (int k = 0; k < 2; ++k) {
      if (q[k] < b.lo[k]) b.lo[k] = q[k];
      if (q[k] > b.hi[k]) b.hi[k] = q[k];
    }
  }
  return b;
}

bool overlap_boxes(const Box2& a, const Box2& b) {
  for (int k = 0; k < 2; ++k) {
    if (a.hi[k] <= b.lo[k] || b.hi[k] <= a.lo[k]) return false;
  }
  return true;
}

/// The line through a -> b as l(p) = A p_x + B p_y + C = (b - a) x (p - a): positive left.
struct Line2 {
  mpq_class a, b, c;
  mpq_class at(const Point2& p) const { return a * p[0] + b * p[1] + c; }
};

Line2 line_through(const Point2& p, const Point2& q) {
  Line2 line{p[1] - q[1], q[0] - p[0], 0};
  line.c = -(line.a * p[0] + line.b * p[1]);
  return line;
}

struct Coverer {
  Polygon2 polygon;  // convex, counter-clockwise
  Box2 box;
  std::vector<Line2> edges;  // edge j runs from vertex j to j + 1
};

enum class Overlap { kNone, kInside, kPartial };

/// Where region r lies relative to coverer g, from the sides of r's vertices alone: all on
/// or right of one edge of g (r and g share no area), all on or left of every edge (r in g),
/// or neither.
Overlap classify(const Polygon2& r, const Coverer& g) {
  bool inside = true;
  for (const Line2& edge : g.edges) {
    bool all_right = true;
    for (const Point2& p : r) {
      const int side = sgn(edge.at(p));
      if (side > 0) all_right = false;
      if (side < 0) inside = false;
    }
    if (all_right) return Overlap::kNone;
  }
  return inside ? Overlap::kInside : Overlap::kPartial;
}

/// True iff `target` minus the union of the coverers has zero area.
bool covered_up_to_zero_area(const Polygon2& target, const std::vector<const Coverer*>& coverers) {
  std::vector<Polygon2> uncovered{target};
  for (const Coverer* g : coverers) {
    std::vector<Polygon2> next;
    for (Polygon2& r : uncovered) {
      const Overlap overlap = overlap_boxes(bounds(r), g->box) ? classify(r, *g) : Overlap::kNone;
      if (overlap == Overlap::kNone) {
        next.push_back(std::move(r));
      } else if (overlap == Overlap::kPartial) {
        for (Polygon2& part : subtract(r, g->polygon)) next.push_back(std::move(part));
      }  // kInside: r is covered
    }
    uncovered = std::move(next);
    if (uncovered.empty()) return true;
  }
  return uncovered.empty();
}

// ---- triangles grouped by their exact plane -----------------------------------------------

/// A plane scaled so that the first non-zero normal component is 1: equal keys iff equal
/// planes. `sign` is the sign of that component in the triangle's own (outward) normal.
struct CanonicalPlane {
  std::array<mpq_class, 4> key;
  int sign = 0;
  int drop = 0;  // the coordinate dropped when projecting (its normal component is non-zero)
};

struct KeyLess {
  bool operator()(const std::array<mpq_class, 4>& a, const std::array<mpq_class, 4>& b) const {
    for (int i = 0; i < 4; ++i) {
      const int c = cmp(a[i], b[i]);
      if (c != 0) return c < 0;
    }
    return false;
  }
};

std::optional<CanonicalPlane> canonical_plane(const RationalVector& a, const RationalVector& b,
                                              const RationalVector& c) {
  const RationalPlane plane = plane_through(a, b, c);
  for (int k = 0; k < 3; ++k) {
    if (sgn(plane.n[k]) == 0) continue;
    const mpq_class& s = plane.n[k];
    return CanonicalPlane{{plane.n[0] / s, plane.n[1] / s, plane.n[2] / s, plane.c / s},
                          sgn(s), k};
  }
  return std::nullopt;  // collinear corners: no plane, covers nothing
}

Polygon2 projected_ccw(const std::array<RationalVector, 3>& corners, int drop) {
  Polygon2 p;
  for (const auto& v : corners) p.push_back({v[(drop + 1) % 3], v[(drop + 2) % 3]});
  if (sgn(twice_area(p)) < 0) std::swap(p[1], p[2]);
  return p;
}

/// A piece facet (the union of the piece's triangles in one plane).
struct PieceFacet {
  Coverer shape;
  int piece = 0;
  int sign = 0;
};

struct PlaneGroup {
  std::vector<Coverer> surface;
  std::vector<PieceFacet> pieces;
};

using PlaneGroups = std::map<std::array<mpq_class, 4>, PlaneGroup, KeyLess>;

Coverer make_coverer(Polygon2 polygon) {
  Coverer coverer;
  coverer.box = bounds(polygon);
  for (std::size_t j = 0; j < polygon.size(); ++j) {
    coverer.edges.push_back(line_through(polygon[j], polygon[(j + 1) % polygon.size()]));
  }
  coverer.polygon = std::move(polygon);
  return coverer;
}

void add_surface(PlaneGroups& groups, const std::vector<Eigen::Vector3d>& vertices,
                 const std::vector<std::array<int, 3>>& triangles) {
  for (const auto& t : triangles) {
    const std::array<RationalVector, 3> c{to_rational(vertices[t[0]]), to_rational(vertices[t[1]]),
                                          to_rational(vertices[t[2]])};
    if (const auto plane = canonical_plane(c[0], c[1], c[2])) {
      groups[plane->key].surface.push_back(make_coverer(projected_ccw(c, plane->drop)));
    }
  }
}

// ---- hypothesis (B): each piece's triangles are its whole boundary ------------------------

std::string piece_boundary_failure(const RationalPiece& piece, std::size_t index) {
  const std::string name = "piece " + std::to_string(index);
  const int n = static_cast<int>(piece.vertices.size());
  if (n < 4 || piece.triangles.size() < 4) return name + " has fewer than 4 vertices or triangles";
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : piece.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || t[k] >= n) return name + " has a triangle index out of range";
      ++directed[{t[k], t[(k + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1) {
      return name + "'s triangles are not a closed oriented surface";
    }
  }
  RationalVector centroid{0, 0, 0};
  for (const auto& v : piece.vertices) {
    centroid[0] += v.x;
    centroid[1] += v.y;
    centroid[2] += v.z;
  }
  for (auto& x : centroid) x /= n;
  for (const auto& t : piece.triangles) {
    const RationalPlane plane = plane_through(to_rational(piece.vertices[t[0]]),
                                              to_rational(piece.vertices[t[1]]),
                                              to_rational(piece.vertices[t[2]]));
    if (dot(plane.n, centroid) >= plane.c) return name + "'s centroid is not strictly inside";
    for (const auto& v : piece.vertices) {
      if (dot(plane.n, to_rational(v)) > plane.c) return name + " has a vertex outside a face";
    }
  }
  return {};
}

/// Convex hull of points, counter-clockwise, without collinear points (monotone chain).
Polygon2 convex_hull_2d(Polygon2 points) {
  std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) {
    const int c = cmp(a[0], b[0]);
    return c != 0 ? c < 0 : cmp(a[1], b[1]) < 0;
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  Polygon2 hull;
  for (int pass = 0; pass < 2; ++pass) {  // lower chain, then upper chain
    const std::size_t start = hull.size();
    for (const Point2& p : points) {
      while (hull.size() >= start + 2 && sgn(side(hull[hull.size() - 2], hull.back(), p)) <= 0) {
        hull.pop_back();
      }
      hull.push_back(p);
    }
    hull.pop_back();  // the last point starts the other chain
    std::reverse(points.begin(), points.end());
  }
  return hull;
}

/// The piece's triangles merged per plane into its facets: for a convex piece whose
/// triangles are its whole boundary (B), the triangles in one plane tile the facet, which is
/// the convex hull of their corners; (F) for the facet is (F) for each of its triangles.
void add_piece(PlaneGroups& groups, const RationalPiece& piece, int index) {
  std::map<std::array<mpq_class, 4>, std::pair<CanonicalPlane, Polygon2>, KeyLess> facets;
  for (const auto& t : piece.triangles) {
    const std::array<RationalVector, 3> c{to_rational(piece.vertices[t[0]]),
                                          to_rational(piece.vertices[t[1]]),
                                          to_rational(piece.vertices[t[2]])};
    const CanonicalPlane plane = *canonical_plane(c[0], c[1], c[2]);  // non-degenerate by (B)
    auto& [facet_plane, corners] = facets[plane.key];
    facet_plane = plane;
    for (const Point2& p : projected_ccw(c, plane.drop)) corners.push_back(p);
  }
  for (auto& [key, facet] : facets) {
    groups[key].pieces.push_back(
        PieceFacet{make_coverer(convex_hull_2d(std::move(facet.second))), index, facet.first.sign});
  }
}

/// Hypothesis (F) for every piece facet.
std::string facet_cover_failure(const PlaneGroups& groups) {
  for (const auto& [key, group] : groups) {
    (void)key;
    for (const PieceFacet& t : group.pieces) {
      std::vector<const Coverer*> coverers;
      for (const Coverer& s : group.surface) coverers.push_back(&s);
      for (const PieceFacet& o : group.pieces) {
        if (o.piece != t.piece && o.sign == -t.sign) coverers.push_back(&o.shape);
      }
      if (!covered_up_to_zero_area(t.shape.polygon, coverers)) {
        return "a facet of piece " + std::to_string(t.piece) +
               " is neither on the surface nor against another piece";
      }
    }
  }
  return {};
}

// ---- outward rounding ---------------------------------------------------------------------

/// The doubles lo <= q <= hi next to q (lo == hi when q is a double). mpq_get_d truncates
/// toward zero, so the other bound is the next double away from zero.
std::pair<double, double> enclosing_doubles(const mpq_class& q) {
  const double truncated = q.get_d();
  if (mpq_class(truncated) == q) return {truncated, truncated};
  const double away = std::nextafter(truncated, sgn(q) > 0 ? std::numeric_limits<double>::infinity()
                                                           : -std::numeric_limits<double>::infinity());
  const auto bounds = sgn(q) > 0 ? std::pair{truncated, away} : std::pair{away, truncated};
  if (!(mpq_class(bounds.first) <= q && q <= mpq_class(bounds.second))) {
    throw std::logic_error("enclosing_doubles: the rational is not bracketed");
  }
  return bounds;
}

}  // namespace

// proof: proofs/shape-containment.md#lemma-exact-cover
ExactCoverCheck verify_exact_cover(const std::vector<RationalPiece>& pieces,
                                   const std::vector<Eigen::Vector3d>& surface_vertices,
                                   const std::vector<std::array<int, 3>>& surface_triangles) {
  if (pieces.empty()) return {false, "no pieces"};
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    std::string failure = piece_boundary_failure(pieces[i], i);
    if (!failure.empty()) return {false, std::move(failure)};
  }
  PlaneGroups groups;
  add_surface(groups, surface_vertices, surface_triangles);
  for (std::size_t i = 0; i < pieces.size(); ++i) add_piece(groups, pieces[i], static_cast<int>(i));
  std::string failure = facet_cover_failure(groups);
  if (!failure.empty()) return {false, std::move(failure)};
  return {true, {}};
}

// proof: proofs/shape-containment.md#lemma-outward-rounding
std::vector<Eigen::Vector3d> enclosing_double_points(const RationalPiece& piece) {
  std::set<std::tuple<double, double, double>> corners;
  for (const RationalPoint& v : piece.vertices) {
    const auto [x0, x1] = enclosing_doubles(v.x);
    const auto [y0, y1] = enclosing_doubles(v.y);
    const auto [z0, z1] = enclosing_doubles(v.z);
    for (const double x : {x0, x1}) {
      for (const double y : {y0, y1}) {
        for (const double z : {z0, z1}) corners.emplace(x, y, z);
      }
    }
  }
  std::vector<Eigen::Vector3d> points;
  for (const auto& [x, y, z] : corners) points.emplace_back(x, y, z);
  return points;
}

}  // namespace grpvss::geometry
