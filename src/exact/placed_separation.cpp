#include "grpvss/exact/placed_separation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/gjk.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;
using namespace rounding;

/// gamma_4 = 4u / (1 - 4u) rounded up: the relative error bound of a sum of four products
/// in any order, with or without fused multiply-add (Higham, Lemma 3.1).
double gamma4_up() {
  const double u = std::numeric_limits<double>::epsilon() / 2;
  return div_up(mul_up(4.0, u), sub_down(1.0, mul_up(4.0, u)));
}

/// The common case of tied_support_upper() with T = {x}, proven while climbing: each visited
/// vertex's neighbours are valued in directed rounding once, and the climb stops where every
/// one of them is at most the vertex's lower value. Returns that vertex's upper value, or
/// nullopt where a neighbour is not clearly below or above (a plateau: left to
/// tied_support_upper, which starts where this climb stopped). Saves the two passes over the
/// end's neighbours that the climb, the tie search and the check would otherwise make. Needs
/// an active UpwardRoundingScope.
/// proof: proofs/fast-path.md#placed-separation (step 2, T = {x})
std::optional<double> climbed_support_upper(const std::vector<Vector3d>& v, const HullSkeleton& skeleton,
                                            const Vector3d& m, int& climb_start) {
  int at = climb_start;
  double at_upper = dot_up(m.data(), v[static_cast<std::size_t>(at)].data());
  for (;;) {
    const double at_lower = dot_down(m.data(), v[static_cast<std::size_t>(at)].data());
    bool every_neighbour_below = true;
    int best = -1;
    double best_upper = at_upper;
    const int end = skeleton.first[static_cast<std::size_t>(at) + 1];
    for (int k = skeleton.first[static_cast<std::size_t>(at)]; k < end; ++k) {
      const int y = skeleton.neighbours[static_cast<std::size_t>(k)];
      const double upper = dot_up(m.data(), v[static_cast<std::size_t>(y)].data());
      if (!(upper <= at_lower)) every_neighbour_below = false;  // NaN counts as not below
      if (upper > best_upper) {
        best = y;
        best_upper = upper;
      }
    }
    climb_start = at;
    if (every_neighbour_below) return std::isfinite(at_upper) ? std::optional<double>(at_upper) : std::nullopt;
    // Each move strictly raises the upper value, so no vertex is visited twice.
    if (best < 0) return std::nullopt;
    at = best;
    at_upper = best_upper;
  }
}

/// Upper bound of \f$\max_i m\cdot v_i\f$ over the template (coordinates at most max_abs),
/// or nullopt. The climb's end x and the vertices connected to it whose values are within
/// `tie` of its value form T; if every
/// neighbour of T outside T is below every member of T (directed rounding), the vertex of T
/// with the largest exact value is a local, hence global, maximum, and the bound is the largest
/// value over T rounded up. Needs an active UpwardRoundingScope.
/// proof: proofs/fast-path.md#placed-separation (step 2)
std::optional<double> tied_support_upper(const std::vector<Vector3d>& v, const HullSkeleton& skeleton,
                                         const Vector3d& m, double max_abs, int& climb_start) {
  const int x = climb_support_index(v, skeleton, climb_start, m);
  climb_start = x;
  const double tie = 1e-12 * (std::fabs(m[0]) + std::fabs(m[1]) + std::fabs(m[2])) * max_abs;
  TiedSupportSet tied;
  if (!tied.gather(v, skeleton, m, x, tie)) return std::nullopt;
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < tied.size(); ++k) {
    const Vector3d& p = v[static_cast<std::size_t>(tied.member(k))];
    lowest = std::min(lowest, dot_down(m.data(), p.data()));
    highest = std::max(highest, dot_up(m.data(), p.data()));
  }
  const bool proven = tied.every_outside_neighbour(skeleton, [&](int y) {
    return dot_up(m.data(), v[static_cast<std::size_t>(y)].data()) <= lowest;
  });
  if (!proven) return std::nullopt;
  return highest;
}

/// Upper bound of \f$\max_i n\cdot \mathrm{fl}(\hat X v_i)\f$ for the placed points of
/// \p hull, or nullopt. Needs an active UpwardRoundingScope.
/// proof: proofs/fast-path.md#placed-separation
std::optional<double> placed_max_upper(const PlacedHull& hull, const Vector3d& n, int& climb_start) {
  const auto& X = hull.X_WL.matrix();
  // m = R^T n in real arithmetic lies in [m_lo, m_lo + spread] componentwise (step 1).
  const RotatedNormal rotated = rotated_normal(hull.X_WL, n);
  const Vector3d& m_lo = rotated.lower;
  const double spread = rotated.spread;
  // The template's support vertices for m_lo: the climb's end and the vertices tied with it
  // (a face or edge facing n), proven to bound every vertex (step 2).
  std::optional<double> top = climbed_support_upper(*hull.vertices_L, *hull.skeleton, m_lo, climb_start);
  if (!top) top = tied_support_upper(*hull.vertices_L, *hull.skeleton, m_lo, hull.max_abs_L, climb_start);
  if (!top) return std::nullopt;
  // max_i m.v_i <= m_lo.v_top + spread V; plus n.t (step 3).
  const double translation[3] = {X(0, 3), X(1, 3), X(2, 3)};
  double bound = add_up(*top, mul_up(spread, hull.max_abs_L));
  bound = add_up(bound, dot_up(n.data(), translation));
  // The placement's own rounding: |fl(Rv + t)_j - (Rv + t)_j| <= gamma_4 (|R_j| V + |t_j|) (step 4).
  double margin = 0.0;
  for (int j = 0; j < 3; ++j) {
    const double row = add_up(add_up(std::fabs(X(j, 0)), std::fabs(X(j, 1))), std::fabs(X(j, 2)));
    const double size = add_up(mul_up(row, hull.max_abs_L), std::fabs(translation[j]));
    margin = add_up(margin, mul_up(std::fabs(n[j]), size));
  }
  bound = add_up(bound, mul_up(gamma4_up(), margin));
  if (!std::isfinite(bound)) return std::nullopt;
  return bound;
}

/// Upper bound of \f$\max n\cdot p\f$ over a set of world points: the scan of
/// [certified-separation](proofs/fast-path.md#certified-separation). Needs an active
/// UpwardRoundingScope.
std::optional<double> max_upper(const std::vector<Vector3d>& points, const Vector3d& n, int&) {
  double offset = -std::numeric_limits<double>::infinity();
  for (const auto& p : points) offset = std::max(offset, dot_up(n.data(), p.data()));
  if (!std::isfinite(offset)) return std::nullopt;
  return offset;
}

std::optional<double> max_upper(const PlacedHull& hull, const Vector3d& n, int& climb_start) {
  return placed_max_upper(hull, n, climb_start);
}

Vector3d point_W(const PlacedHull& hull, int i) { return hull.point_W(i); }
Vector3d point_W(const std::vector<Vector3d>& points, int i) { return points[static_cast<std::size_t>(i)]; }

template <class SetB>
std::optional<CertifiedSeparation> certify(const PlacedHull& a, int& a_climb_start, const SetB& b,
                                           int& b_climb_start, const Vector3d& normal_AB) {
  // proof: proofs/fast-path.md#placed-separation
  if (!normal_AB.allFinite() || (normal_AB.array() == 0.0).all()) return std::nullopt;
  const UpwardRoundingScope upward;
  const std::optional<double> offset_a = max_upper(a, normal_AB, a_climb_start);
  if (!offset_a) return std::nullopt;
  const std::optional<double> minus_offset_b = max_upper(b, -normal_AB, b_climb_start);
  if (!minus_offset_b) return std::nullopt;
  return slab_between(normal_AB, *offset_a, -*minus_offset_b);
}

/// The proposals of certified_pair_query() in its order (proofs/fast-path.md#certified-query),
/// each proven by certify().
template <class SetB>
std::optional<CertifiedPairResult> query(const PlacedHull& a, const SetB& b, const GjkResult& g,
                                         const Vector3d* warm_start_direction) {
  int a_start = g.last_support_a;
  int b_start = g.last_support_b;
  if (g.status == GjkStatus::kSeparated) {
    if (auto s = certify(a, a_start, b, b_start, -g.closest_vector)) return filter_separation(*s, g.distance);
    if (g.simplex_size == 3) {
      const Vector3d w0 = a.point_W(g.simplex_a[0]) - point_W(b, g.simplex_b[0]);
      const Vector3d w1 = a.point_W(g.simplex_a[1]) - point_W(b, g.simplex_b[1]);
      const Vector3d w2 = a.point_W(g.simplex_a[2]) - point_W(b, g.simplex_b[2]);
      Vector3d n = (w1 - w0).cross(w2 - w0);
      if (n.dot(g.closest_vector) > 0.0) n = -n;
      if (auto s = certify(a, a_start, b, b_start, n)) return filter_separation(*s, g.distance);
    }
  }
  if (warm_start_direction != nullptr && g.status != GjkStatus::kSeparated) {
    if (auto s = certify(a, a_start, b, b_start, *warm_start_direction)) {
      return filter_separation(*s, g.distance);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<CertifiedSeparation> certify_placed_separation(const PlacedHull& a, int& a_climb_start,
                                                             const PlacedHull& b, int& b_climb_start,
                                                             const Vector3d& normal_AB) {
  return certify(a, a_climb_start, b, b_climb_start, normal_AB);
}

std::optional<CertifiedSeparation> certify_placed_separation(const PlacedHull& a, int& a_climb_start,
                                                             const std::vector<Vector3d>& b,
                                                             const Vector3d& normal_AB) {
  int unused = 0;
  return certify(a, a_climb_start, b, unused, normal_AB);
}

std::optional<CertifiedPairResult> certified_placed_separation_query(
    const PlacedHull& a, const PlacedHull& b, const Vector3d* warm_start_direction,
    int* a_climb_hint, int* b_climb_hint, GjkSimplexHint* simplex_hint) {
  const GjkResult g = gjk(a, b, warm_start_direction, a_climb_hint ? *a_climb_hint : 0,
                          b_climb_hint ? *b_climb_hint : 0, simplex_hint);
  if (a_climb_hint) *a_climb_hint = g.last_support_a;
  if (b_climb_hint) *b_climb_hint = g.last_support_b;
  return query(a, b, g, warm_start_direction);
}

std::optional<CertifiedPairResult> certified_placed_separation_query(
    const PlacedHull& a, const std::vector<Vector3d>& b, const Vector3d* warm_start_direction,
    int* a_climb_hint, GjkSimplexHint* simplex_hint) {
  if (b.empty()) throw std::invalid_argument("certified_placed_separation_query: empty point set");
  const GjkResult g = gjk(a, b, warm_start_direction, a_climb_hint ? *a_climb_hint : 0, simplex_hint);
  if (a_climb_hint) *a_climb_hint = g.last_support_a;
  return query(a, b, g, warm_start_direction);
}

}  // namespace grpvss::geometry
