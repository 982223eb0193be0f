#include "grpvss/exact/certified_query.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;
using namespace rounding;

/// Closed interval [lo, hi]; every operation below requires an active UpwardRoundingScope.
struct Interval {
  double lo;
  double hi;
};

Interval operator+(Interval x, Interval y) { return {add_down(x.lo, y.lo), add_up(x.hi, y.hi)}; }
Interval operator-(Interval x, Interval y) { return {sub_down(x.lo, y.hi), sub_up(x.hi, y.lo)}; }
Interval operator*(Interval x, Interval y) {
  const double lo = std::min({mul_down(x.lo, y.lo), mul_down(x.lo, y.hi), mul_down(x.hi, y.lo),
                              mul_down(x.hi, y.hi)});
  const double hi = std::max({mul_up(x.lo, y.lo), mul_up(x.lo, y.hi), mul_up(x.hi, y.lo),
                              mul_up(x.hi, y.hi)});
  return {lo, hi};
}

struct IntervalPoint {
  Interval c[3];
};

IntervalPoint operator-(const IntervalPoint& p, const IntervalPoint& q) {
  return {{p.c[0] - q.c[0], p.c[1] - q.c[1], p.c[2] - q.c[2]}};
}

/// Encloses \f$\det[q - p, r - p, s - p]\f$ for every choice of points in the boxes.
Interval orientation(const IntervalPoint& p, const IntervalPoint& q, const IntervalPoint& r,
                     const IntervalPoint& s) {
  const IntervalPoint u = q - p, v = r - p, w = s - p;
  return u.c[0] * (v.c[1] * w.c[2] - v.c[2] * w.c[1]) -
         u.c[1] * (v.c[0] * w.c[2] - v.c[2] * w.c[0]) +
         u.c[2] * (v.c[0] * w.c[1] - v.c[1] * w.c[0]);
}

/// +1 / -1 if the interval is strictly positive / negative, 0 if it is not conclusive.
int certain_sign(Interval x) { return x.lo > 0.0 ? 1 : (x.hi < 0.0 ? -1 : 0); }

/// Marks the hull vertices of \p p equal to points[indices[k]], k < count.
std::vector<bool> marked_vertices(const ConvexPolytope& p, const std::vector<Vector3d>& points,
                                  const int* indices, int count) {
  std::vector<bool> marked(p.vertices().size(), false);
  for (int k = 0; k < count; ++k) {
    for (std::size_t v = 0; v < p.vertices().size(); ++v) {
      if (p.vertices()[v] == points[indices[k]]) marked[v] = true;
    }
  }
  return marked;
}

/// Near contact, the GJK direction is too inexact, but facet normals of A - B are computed
/// from hull features to relative accuracy ~1e-16. Candidates: faces of A or B and
/// edge(A) x edge(B) directions at the hull vertices of GJK's final simplex. Each is only a
/// proposal: certify_separation() proves it or rejects it.
std::optional<CertifiedSeparation> certify_by_features(const std::vector<Vector3d>& a,
                                                       const std::vector<Vector3d>& b,
                                                       const ConvexPolytope& pa,
                                                       const ConvexPolytope& pb,
                                                       const GjkResult& g) {
  const std::vector<bool> near_a = marked_vertices(pa, a, g.simplex_a.data(), g.simplex_size);
  const std::vector<bool> near_b = marked_vertices(pb, b, g.simplex_b.data(), g.simplex_size);
  std::optional<CertifiedSeparation> best;
  const auto consider = [&](const Vector3d& normal_AB) {
    auto s = certify_separation(a, b, normal_AB);
    if (s && (!best || s->lower_bound > best->lower_bound)) best = s;
  };
  const auto face_normals = [](const ConvexPolytope& p, const std::vector<bool>& near, double sign,
                               const auto& use) {
    for (const auto& face : p.faces()) {
      if (std::none_of(face.begin(), face.end(), [&](int v) { return near[v]; })) continue;
      const Vector3d& v0 = p.vertices()[face[0]];
      use(sign * (p.vertices()[face[1]] - v0).cross(p.vertices()[face[2]] - v0));
    }
  };
  face_normals(pa, near_a, 1.0, consider);   // outward normal of A points towards B
  face_normals(pb, near_b, -1.0, consider);  // outward normal of B points towards A
  for (const auto& ea : pa.edges()) {
    if (!near_a[ea[0]] && !near_a[ea[1]]) continue;
    const Vector3d da = pa.vertices()[ea[1]] - pa.vertices()[ea[0]];
    for (const auto& eb : pb.edges()) {
      if (!near_b[eb[0]] && !near_b[eb[1]]) continue;
      const Vector3d n = da.cross(pb.vertices()[eb[1]] - pb.vertices()[eb[0]]);
      consider(n);
      consider(-n);
    }
  }
  return best;
}

CertifiedPairResult from_exact(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b,
                               const GjkResult& g) {
  CertifiedPairResult result;
  result.decided_by = DecidedBy::kExactFallback;
  result.distance_estimate = g.status == GjkStatus::kSeparated ? g.distance : 0.0;
  // Exact hulls built once, for the classification and for the feature normals.
  const ConvexPolytope pa = ConvexPolytope::from_points(a);
  const ConvexPolytope pb = ConvexPolytope::from_points(b);
  result.contact = classify_exact(pa, pb);
  if (result.contact == Contact::kSeparated) {
    if (auto s = certify_by_features(a, b, pa, pb, g)) {
      result.witness = s->witness;
      result.clearance_lower_bound = s->lower_bound;
      return result;
    }
    // Only for gaps below what double normals can resolve (about 1e-15 of the extent). The
    // exact core may still find no double slab (gap below the witness format's resolution):
    // the pair stays kSeparated (decided exactly) with no witness and clearance 0.
    result.witness = exact_separation_witness(a, b);
    if (result.witness) result.clearance_lower_bound = certified_lower_bound(*result.witness);
  }
  return result;
}

}  // namespace

const char* to_string(DecidedBy decided_by) {
  switch (decided_by) {
    case DecidedBy::kIntervalFilter: return "interval-filter";
    case DecidedBy::kExactFallback: return "exact-fallback";
  }
  return "unknown";
}

std::optional<CertifiedSeparation> certify_separation(const std::vector<Vector3d>& a,
                                                      const std::vector<Vector3d>& b,
                                                      const Vector3d& normal_AB) {
  // proof: proofs/fast-path.md#certified-separation
  if (!normal_AB.allFinite() || (normal_AB.array() == 0.0).all()) return std::nullopt;
  const UpwardRoundingScope upward;
  const double* n = normal_AB.data();
  double offset_a = -std::numeric_limits<double>::infinity();
  for (const auto& p : a) offset_a = std::max(offset_a, dot_up(n, p.data()));
  double offset_b = std::numeric_limits<double>::infinity();
  for (const auto& p : b) offset_b = std::min(offset_b, dot_down(n, p.data()));
  return slab_between(normal_AB, offset_a, offset_b);
}

std::optional<CertifiedSeparation> slab_between(const Vector3d& normal_AB, double offset_a,
                                                double offset_b) {
  if (!(offset_b > offset_a) || !std::isfinite(offset_a) || !std::isfinite(offset_b)) {
    return std::nullopt;
  }
  const double* n = normal_AB.data();
  const double norm_up =
      sqrt_up(add_up(add_up(mul_up(n[0], n[0]), mul_up(n[1], n[1])), mul_up(n[2], n[2])));
  CertifiedSeparation out;
  out.witness.normal = normal_AB;
  out.witness.offset_a = offset_a;
  out.witness.offset_b = offset_b;
  out.lower_bound = std::max(0.0, div_down(sub_down(offset_b, offset_a), norm_up));
  return out;
}

CertifiedPairResult filter_separation(const CertifiedSeparation& separation, double distance_estimate) {
  CertifiedPairResult result;
  result.contact = Contact::kSeparated;
  result.witness = separation.witness;
  result.clearance_lower_bound = separation.lower_bound;
  result.distance_estimate = distance_estimate;
  result.decided_by = DecidedBy::kIntervalFilter;
  return result;
}

bool certify_overlap(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b,
                     const std::array<int, 4>& ia, const std::array<int, 4>& ib) {
  // proof: proofs/fast-path.md#certified-overlap
  const UpwardRoundingScope upward;
  IntervalPoint w[4];
  for (int k = 0; k < 4; ++k) {
    const Vector3d& p = a.at(ia[k]);
    const Vector3d& q = b.at(ib[k]);
    for (int c = 0; c < 3; ++c) w[k].c[c] = {sub_down(p[c], q[c]), sub_up(p[c], q[c])};
  }
  const IntervalPoint origin{{{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}}};
  // D_k = orientation with vertex k replaced by the origin; all of one strict sign means
  // every barycentric coordinate D_k / sum(D) of the origin is positive.
  const int s0 = certain_sign(orientation(origin, w[1], w[2], w[3]));
  if (s0 == 0) return false;
  return certain_sign(orientation(w[0], origin, w[2], w[3])) == s0 &&
         certain_sign(orientation(w[0], w[1], origin, w[3])) == s0 &&
         certain_sign(orientation(w[0], w[1], w[2], origin)) == s0;
}

CertifiedPairResult certified_pair_query(const std::vector<Vector3d>& a,
                                         const std::vector<Vector3d>& b,
                                         const Vector3d* warm_start_direction,
                                         const HullSkeleton* a_skeleton, int* a_climb_hint,
                                         const HullSkeleton* b_skeleton, int* b_climb_hint) {
  const GjkResult g = gjk(a, b, warm_start_direction, a_skeleton, a_climb_hint ? *a_climb_hint : 0,
                          b_skeleton, b_climb_hint ? *b_climb_hint : 0);
  if (a_climb_hint) *a_climb_hint = g.last_support_a;
  if (b_climb_hint) *b_climb_hint = g.last_support_b;
  if (g.status == GjkStatus::kOverlapping &&
      certify_overlap(a, b, g.simplex_a, g.simplex_b)) {
    CertifiedPairResult result;
    result.contact = Contact::kOverlapping;
    result.decided_by = DecidedBy::kIntervalFilter;
    return result;
  }
  if (g.status == GjkStatus::kSeparated) {
    // First the closest-point direction, then (near contact, where rounding of v hurts) the
    // normal of the final simplex triangle, which is a facet normal of A - B.
    if (auto s = certify_separation(a, b, -g.closest_vector)) {
      return filter_separation(*s, g.distance);
    }
    if (g.simplex_size == 3) {
      const Vector3d w0 = a[g.simplex_a[0]] - b[g.simplex_b[0]];
      const Vector3d w1 = a[g.simplex_a[1]] - b[g.simplex_b[1]];
      const Vector3d w2 = a[g.simplex_a[2]] - b[g.simplex_b[2]];
      Vector3d n = (w1 - w0).cross(w2 - w0);
      if (n.dot(g.closest_vector) > 0.0) n = -n;
      if (auto s = certify_separation(a, b, n)) return filter_separation(*s, g.distance);
    }
  }
  // Double GJK misjudges near-degenerate simplices (CAD hulls have many coplanar vertices) and
  // may claim an overlap the interval test cannot confirm; the caller's warm normal (the last
  // witness of this pair) often still separates, and one more scan costs far less than the
  // exact SAT over every edge pair of two big hulls. The slab is decided over every point
  // as any other. proof: proofs/fast-path.md#certified-separation
  if (warm_start_direction != nullptr && g.status != GjkStatus::kSeparated) {
    if (auto s = certify_separation(a, b, *warm_start_direction)) {
      return filter_separation(*s, g.distance);
    }
  }
  return from_exact(a, b, g);
}

}  // namespace grpvss::geometry
