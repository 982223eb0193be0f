#include "grpvss/geometry/gjk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

/// One simplex vertex: w = a[ia] - b[ib].
struct SimplexVertex {
  Vector3d w = Vector3d::Zero();
  int ia = 0;
  int ib = 0;
};

/// A simplex with barycentric weights of its closest point to the origin.
struct Simplex {
  std::array<SimplexVertex, 4> v;
  std::array<double, 4> weight{};
  int size = 0;
  bool contains_origin = false;  // only meaningful for size 4
};

Simplex make(std::initializer_list<std::pair<const SimplexVertex*, double>> items) {
  Simplex s;
  for (const auto& [vertex, weight] : items) {
    s.v[s.size] = *vertex;
    s.weight[s.size] = weight;
    ++s.size;
  }
  return s;
}

Vector3d point_of(const Simplex& s) {
  Vector3d p = Vector3d::Zero();
  for (int k = 0; k < s.size; ++k) p += s.weight[k] * s.v[k].w;
  return p;
}

Simplex closest_on_segment(const SimplexVertex& a, const SimplexVertex& b) {
  const Vector3d ab = b.w - a.w;
  const double denom = ab.squaredNorm();
  const double t = denom > 0.0 ? -a.w.dot(ab) / denom : 0.0;
  if (t <= 0.0) return make({{&a, 1.0}});
  if (t >= 1.0) return make({{&b, 1.0}});
  return make({{&a, 1.0 - t}, {&b, t}});
}

// Ericson, Real-Time Collision Detection, 5.1.5, with the query point at the origin.
Simplex closest_on_triangle(const SimplexVertex& a, const SimplexVertex& b,
                            const SimplexVertex& c) {
  const Vector3d ab = b.w - a.w;
  const Vector3d ac = c.w - a.w;
  const double d1 = -ab.dot(a.w);
  const double d2 = -ac.dot(a.w);
  if (d1 <= 0.0 && d2 <= 0.0) return make({{&a, 1.0}});
  const double d3 = -ab.dot(b.w);
  const double d4 = -ac.dot(b.w);
  if (d3 >= 0.0 && d4 <= d3) return make({{&b, 1.0}});
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double t = d1 / (d1 - d3);
    return make({{&a, 1.0 - t}, {&b, t}});
  }
  const double d5 = -ab.dot(c.w);
  const double d6 = -ac.dot(c.w);
  if (d6 >= 0.0 && d5 <= d6) return make({{&c, 1.0}});
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double t = d2 / (d2 - d6);
    return make({{&a, 1.0 - t}, {&c, t}});
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make({{&b, 1.0 - t}, {&c, t}});
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return closest_on_segment(a, b);  // degenerate (collinear) triangle
  const double v = vb / sum;
  const double w = vc / sum;
  return make({{&a, 1.0 - v - w}, {&b, v}, {&c, w}});
}

/// True when the origin and \p d lie strictly on different sides of plane (a, b, c), or the
/// tetrahedron is flat (then every face must be examined).
bool origin_outside_face(const Vector3d& a, const Vector3d& b, const Vector3d& c,
                         const Vector3d& d) {
  const Vector3d n = (b - a).cross(c - a);
  const double sign_origin = -a.dot(n);
  const double sign_d = (d - a).dot(n);
  if (sign_d == 0.0) return true;
  return sign_origin * sign_d <= 0.0;
}

Simplex closest_on_tetrahedron(const SimplexVertex& a, const SimplexVertex& b,
                               const SimplexVertex& c, const SimplexVertex& d) {
  Simplex best;
  double best_norm2 = std::numeric_limits<double>::infinity();
  bool any_outside = false;
  const auto consider = [&](const SimplexVertex& p, const SimplexVertex& q,
                            const SimplexVertex& r, const SimplexVertex& opposite) {
    if (!origin_outside_face(p.w, q.w, r.w, opposite.w)) return;
    any_outside = true;
    const Simplex s = closest_on_triangle(p, q, r);
    const double n2 = point_of(s).squaredNorm();
    if (n2 < best_norm2) {
      best_norm2 = n2;
      best = s;
    }
  };
  consider(a, b, c, d);
  consider(a, c, d, b);
  consider(a, d, b, c);
  consider(b, d, c, a);
  if (!any_outside) {
    Simplex inside = make({{&a, 0.25}, {&b, 0.25}, {&c, 0.25}, {&d, 0.25}});
    inside.contains_origin = true;
    return inside;
  }
  return best;
}

Simplex closest(const Simplex& s) {
  switch (s.size) {
    case 1: return s;
    case 2: return closest_on_segment(s.v[0], s.v[1]);
    case 3: return closest_on_triangle(s.v[0], s.v[1], s.v[2]);
    case 4: return closest_on_tetrahedron(s.v[0], s.v[1], s.v[2], s.v[3]);
    default: throw std::logic_error("gjk: simplex of invalid size");
  }
}

/// A point set given as vectors: support points by a scan, or by climbing its skeleton from
/// where the last support was found.
struct VectorSet {
  const std::vector<Vector3d>* points = nullptr;
  const HullSkeleton* skeleton = nullptr;
  int start = 0;

  const Vector3d& point(int i) const { return (*points)[static_cast<std::size_t>(i)]; }
  int size() const { return static_cast<int>(points->size()); }
  // Always inlined: GJK calls this twice per iteration on the thesis's 8-16-vertex hulls.
  [[gnu::always_inline]] int support(const Vector3d& d) const {
    return skeleton ? climb_support_index(*points, *skeleton, start, d) : support_index(*points, d);
  }
};

/// A link-frame hull under its placement: the support of the placed set in direction d is the
/// placed support of the template in direction R^T d, so only the points GJK visits are placed.
struct PlacedSet {
  const PlacedHull* hull = nullptr;
  int start = 0;

  Vector3d point(int i) const { return hull->point_W(i); }
  int size() const { return static_cast<int>(hull->vertices_L->size()); }
  int support(const Vector3d& d_W) const {
    const Vector3d d_L = hull->X_WL.linear().transpose() * d_W;
    return climb_support_index(*hull->vertices_L, *hull->skeleton, start, d_L);
  }
};

/// The support point of A - B in direction d.
template <class SetA, class SetB>
[[gnu::always_inline]] inline SimplexVertex support(const SetA& a, const SetB& b, const Vector3d& d) {
  const int ia = a.support(d);
  const int ib = b.support(-d);
  return {a.point(ia) - b.point(ib), ia, ib};
}

VectorSet checked_set(const std::vector<Vector3d>& points, const HullSkeleton* skeleton, int start) {
  if (skeleton && skeleton->point_count() != static_cast<int>(points.size())) {
    throw std::invalid_argument("gjk: the skeleton does not fit the point set");
  }
  if (start < 0 || start >= static_cast<int>(points.size())) start = 0;
  return {&points, skeleton, start};
}

PlacedSet checked_set(const PlacedHull& hull, int start) {
  if (hull.vertices_L == nullptr || hull.skeleton == nullptr || hull.vertices_L->empty() ||
      hull.skeleton->point_count() != static_cast<int>(hull.vertices_L->size())) {
    throw std::invalid_argument("gjk: a placed hull needs its vertices and their skeleton");
  }
  if (start < 0 || start >= static_cast<int>(hull.vertices_L->size())) start = 0;
  return {&hull, start};
}

template <class SetA, class SetB>
void fill_result(const Simplex& s, const SetA& a, const SetB& b, GjkResult& result) {
  result.simplex_size = s.size;
  result.closest_a.setZero();
  result.closest_b.setZero();
  for (int k = 0; k < s.size; ++k) {
    result.simplex_a[k] = s.v[k].ia;
    result.simplex_b[k] = s.v[k].ib;
    result.closest_a += s.weight[k] * a.point(s.v[k].ia);
    result.closest_b += s.weight[k] * b.point(s.v[k].ib);
  }
  result.closest_vector = point_of(s);
}

constexpr int kMaxIterations = 64;
// Convergence: the duality gap |v|^2 - v.w is a relative bound on how far |v| may still fall.
constexpr double kRelativeGap = 1e-13;
// Below this fraction of the sets' extent, double GJK cannot tell touching from a tiny gap.
constexpr double kRelativeContact = 1e-14;

}  // namespace

int support_index(const std::vector<Vector3d>& points, const Vector3d& d) {
  int best = 0;
  double best_value = points[0].dot(d);
  for (int i = 1; i < static_cast<int>(points.size()); ++i) {
    const double value = points[i].dot(d);
    if (value > best_value) {
      best_value = value;
      best = i;
    }
  }
  return best;
}

namespace {

/// The previous query's simplex at the sets' new places, reduced to its closest feature; false
/// when there is none (or an index is out of range).
template <class SetA, class SetB>
bool start_from_simplex(const SetA& a, const SetB& b, const GjkSimplexHint* hint, Simplex& simplex) {
  if (hint == nullptr || hint->size < 1 || hint->size > 3) return false;
  Simplex previous;
  for (int k = 0; k < hint->size; ++k) {
    const int ia = hint->a[static_cast<std::size_t>(k)];
    const int ib = hint->b[static_cast<std::size_t>(k)];
    if (ia < 0 || ia >= a.size() || ib < 0 || ib >= b.size()) return false;
    previous.v[static_cast<std::size_t>(k)] = {a.point(ia) - b.point(ib), ia, ib};
    previous.weight[static_cast<std::size_t>(k)] = 0.0;
  }
  previous.size = hint->size;
  if (previous.size == 1) previous.weight[0] = 1.0;
  simplex = closest(previous);
  return true;
}

template <class SetA, class SetB>
GjkResult run_gjk(SetA& a, SetB& b, const Vector3d* warm_start_normal,
                  const GjkSimplexHint* simplex_hint = nullptr) {
  GjkResult result;
  // n separates A (below) from B (above), so the first useful support direction of A - B is
  // -v = n; without a warm start use the direction from a[0] to b[0].
  // Exact zero tests: Eigen's isZero() is fuzzy (|x| <= 1e-12) and tiny vectors matter here.
  const bool warm = warm_start_normal != nullptr && !(warm_start_normal->array() == 0.0).all();
  Vector3d direction = warm ? *warm_start_normal : Vector3d(b.point(0) - a.point(0));
  if ((direction.array() == 0.0).all()) direction = Vector3d::UnitX();
  Simplex simplex;
  double scale2 = 0.0;
  if (start_from_simplex(a, b, simplex_hint, simplex)) {
    for (int k = 0; k < simplex.size; ++k) scale2 = std::max(scale2, simplex.v[static_cast<std::size_t>(k)].w.squaredNorm());
    result.last_support_a = a.start = simplex.v[0].ia;
    result.last_support_b = b.start = simplex.v[0].ib;
  } else {
    simplex.v[0] = support(a, b, direction);
    simplex.weight[0] = 1.0;
    simplex.size = 1;
    result.last_support_a = a.start = simplex.v[0].ia;
    result.last_support_b = b.start = simplex.v[0].ib;
    scale2 = simplex.v[0].w.squaredNorm();
  }
  Vector3d v = point_of(simplex);

  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    result.iterations = iteration;
    const double v2 = v.squaredNorm();
    if (v2 <= kRelativeContact * kRelativeContact * scale2) {
      fill_result(simplex, a, b, result);
      result.status = GjkStatus::kNearContact;
      return result;
    }
    // The supports move little between iterations: climb from the last ones.
    const SimplexVertex w = support(a, b, -v);
    result.last_support_a = a.start = w.ia;
    result.last_support_b = b.start = w.ib;
    scale2 = std::max(scale2, w.w.squaredNorm());
    const bool repeated = std::any_of(simplex.v.begin(), simplex.v.begin() + simplex.size,
                                      [&](const SimplexVertex& s) {
                                        return s.ia == w.ia && s.ib == w.ib;
                                      });
    if (repeated || v2 - v.dot(w.w) <= kRelativeGap * v2) {
      fill_result(simplex, a, b, result);
      result.distance = std::sqrt(v2);
      result.status = GjkStatus::kSeparated;
      return result;
    }
    const Simplex previous = simplex;
    simplex.v[simplex.size] = w;
    ++simplex.size;
    const Simplex reduced = closest(simplex);
    if (reduced.contains_origin) {
      fill_result(reduced, a, b, result);
      result.closest_vector.setZero();
      result.status = GjkStatus::kOverlapping;
      return result;
    }
    const Vector3d next_v = point_of(reduced);
    // GJK's |v| must strictly fall; if rounding stalls it, stop with the best estimate.
    if (next_v.squaredNorm() >= v2) {
      fill_result(previous, a, b, result);
      result.distance = std::sqrt(v2);
      result.status = GjkStatus::kSeparated;
      return result;
    }
    simplex = reduced;
    v = next_v;
  }
  fill_result(simplex, a, b, result);
  result.distance = v.norm();
  result.status = GjkStatus::kSeparated;
  return result;
}

// A separated pair's final simplex is where its next query starts; anything else starts afresh.
void keep_simplex(const GjkResult& result, GjkSimplexHint* hint) {
  if (hint == nullptr) return;
  hint->size = result.status == GjkStatus::kSeparated ? result.simplex_size : 0;
  hint->a = result.simplex_a;
  hint->b = result.simplex_b;
}

}  // namespace

GjkResult gjk(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b,
              const Vector3d* warm_start_normal, const HullSkeleton* a_skeleton,
              int a_climb_start, const HullSkeleton* b_skeleton, int b_climb_start) {
  if (a.empty() || b.empty()) throw std::invalid_argument("gjk: empty point set");
  VectorSet a_set = checked_set(a, a_skeleton, a_climb_start);
  VectorSet b_set = checked_set(b, b_skeleton, b_climb_start);
  return run_gjk(a_set, b_set, warm_start_normal);
}

GjkResult gjk(const PlacedHull& a, const PlacedHull& b, const Vector3d* warm_start_normal,
              int a_climb_start, int b_climb_start, GjkSimplexHint* simplex_hint) {
  PlacedSet a_set = checked_set(a, a_climb_start);
  PlacedSet b_set = checked_set(b, b_climb_start);
  const GjkResult result = run_gjk(a_set, b_set, warm_start_normal, simplex_hint);
  keep_simplex(result, simplex_hint);
  return result;
}

GjkResult gjk(const PlacedHull& a, const std::vector<Vector3d>& b, const Vector3d* warm_start_normal,
              int a_climb_start, GjkSimplexHint* simplex_hint) {
  if (b.empty()) throw std::invalid_argument("gjk: empty point set");
  PlacedSet a_set = checked_set(a, a_climb_start);
  VectorSet b_set = checked_set(b, nullptr, 0);
  const GjkResult result = run_gjk(a_set, b_set, warm_start_normal, simplex_hint);
  keep_simplex(result, simplex_hint);
  return result;
}

}  // namespace grpvss::geometry
