// The thesis's robot expansion (Section 4.2.1), step by step, in a chosen floating type.
// Deliberately NOT robust beyond what the thesis did: it exists to be audited
// (docs/expansion-audit.md). The reading of ambiguous steps is documented in the header.
#include "grpvss/geometry/thesis_expansion.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace grpvss::geometry {
namespace {

constexpr int kCapSize = kThesisPrismVertexCount / 2;

template <typename Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;

/// Index of cap vertex `offset` steps from `index` within the same cap (cyclic).
int cap_neighbour(int index, int offset) {
  const int cap_start = index < kCapSize ? 0 : kCapSize;
  const int local = ((index - cap_start + offset) % kCapSize + kCapSize) % kCapSize;
  return cap_start + local;
}

/// Partner of a vertex on the other cap (thesis Figure 7: vertex k and vertex k+8).
int partner(int index) { return index < kCapSize ? index + kCapSize : index - kCapSize; }

/// Newell's normal of the cap polygon starting at `cap_start` (our choice for the text's N;
/// it tolerates collinear consecutive vertices, unlike a single cross product).
template <typename Scalar>
Vec3<Scalar> newell_normal(const std::array<Vec3<Scalar>, kThesisPrismVertexCount>& p,
                           int cap_start) {
  Vec3<Scalar> normal = Vec3<Scalar>::Zero();
  for (int i = 0; i < kCapSize; ++i) {
    const Vec3<Scalar>& a = p[cap_start + i];
    const Vec3<Scalar>& b = p[cap_start + (i + 1) % kCapSize];
    normal.x() += (a.y() - b.y()) * (a.z() + b.z());
    normal.y() += (a.z() - b.z()) * (a.x() + b.x());
    normal.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  return normal;
}

/// The parallel line of one cap edge (Eq. 4-1, 4-2): base point and direction.
template <typename Scalar>
struct OffsetLine {
  Vec3<Scalar> base;       // P_l
  Vec3<Scalar> direction;  // P_3 - P_2
};

template <typename Scalar>
struct EdgeOffsetResult {
  OffsetLine<Scalar> line;
  bool origin_on_plane = false;
  bool degenerate_in_plane_sign = false;
  bool in_plane_minus = false;
};

/// Edge P2 -> P3 with P1 before P2 and P4 after P3 (all on the same cap), N the cap normal,
/// Q the partner of P3 on the other cap (our reading of "P3" in the Eq. 4-2 sign rule).
template <typename Scalar>
EdgeOffsetResult<Scalar> offset_edge(const Vec3<Scalar>& p1, const Vec3<Scalar>& p2,
                                     const Vec3<Scalar>& p3, const Vec3<Scalar>& p4,
                                     const Vec3<Scalar>& q, const Vec3<Scalar>& normal,
                                     Scalar delta) {
  EdgeOffsetResult<Scalar> result;
  const Vec3<Scalar> direction = p3 - p2;

  // Eq. 4-1: P0 = P3 +- (P3-P2) x N / |(P3-P2) x N| * Delta.
  const Vec3<Scalar> cross = direction.cross(normal);
  const Scalar cross_norm = cross.norm();
  if (!(cross_norm > Scalar(0))) {
    throw std::invalid_argument("thesis expansion: zero-length cap edge");
  }
  const Vec3<Scalar> step_plus = cross / cross_norm * delta;  // P0(+) - P3
  // Sign of Eq. 4-1: "+" iff (P0-P3).(P4-P3) <= 0 or (P0-P3).(P1-P3) <= 0, read as: the
  // product with the larger magnitude decides (the other may be 0 for a collinear neighbour).
  const Scalar test_next = step_plus.dot(p4 - p3);
  const Scalar test_prev = step_plus.dot(p1 - p3);
  const Scalar decisive = std::abs(test_next) >= std::abs(test_prev) ? test_next : test_prev;
  result.degenerate_in_plane_sign = test_next == Scalar(0) && test_prev == Scalar(0);
  result.in_plane_minus = !(decisive <= Scalar(0));
  const Vec3<Scalar> p0 = decisive <= Scalar(0) ? Vec3<Scalar>(p3 + step_plus)
                                                 : Vec3<Scalar>(p3 - step_plus);

  // Eq. 4-2: P_l = P0 +- N/|N| * Delta. The plane is Ax+By+Cz+D = 0 with (A,B,C) = N through
  // P3, so D = -N.P3; the value at the origin is D, at Q it is N.Q + D.
  const Scalar d = -normal.dot(p3);
  const Scalar side_origin = d;
  const Scalar side_hull = normal.dot(q) + d;
  // "N points to the origin" <=> the origin is on N's positive side (D > 0).
  const bool different_sides = side_origin * side_hull < Scalar(0);
  const bool same_side = side_origin * side_hull > Scalar(0);
  const bool n_points_to_origin = side_origin > Scalar(0);
  const bool n_points_away_from_origin = side_origin < Scalar(0);
  const bool plus = (different_sides && n_points_to_origin) ||
                    (same_side && n_points_away_from_origin);
  result.origin_on_plane = side_origin == Scalar(0);
  const Vec3<Scalar> normal_step = normal / normal.norm() * delta;
  result.line.base = plus ? Vec3<Scalar>(p0 + normal_step) : Vec3<Scalar>(p0 - normal_step);
  result.line.direction = direction;
  return result;
}

/// Eq. 4-3 .. 4-12: midpoint of the shortest segment between two lines, and its length.
template <typename Scalar>
struct Midpoint {
  Vec3<Scalar> point;
  Scalar gap = 0;
  bool parallel = false;
};

template <typename Scalar>
Midpoint<Scalar> closest_midpoint(const OffsetLine<Scalar>& line1,
                                  const OffsetLine<Scalar>& line2) {
  const Vec3<Scalar>& p1 = line1.base;
  const Vec3<Scalar>& d1 = line1.direction;
  const Vec3<Scalar>& p2 = line2.base;
  const Vec3<Scalar>& d2 = line2.direction;
  const Scalar d1d1 = d1.dot(d1);
  const Scalar d2d2 = d2.dot(d2);
  const Scalar d1d2 = d1.dot(d2);
  const Scalar d1_p2p1 = d1.dot(p2 - p1);  // d1^t (P2 - P1)
  const Scalar d2_p1p2 = d2.dot(p1 - p2);  // d2^t (P1 - P2)
  const Scalar deno = d1d1 * d2d2 - d1d2 * d1d2;

  Midpoint<Scalar> result;
  Scalar lambda1 = 0;
  Scalar lambda2 = 0;
  if (deno == Scalar(0)) {
    // Parallel lines: "arbitrarily pick lambda1*" (we pick 0) and Eq. 4-5 gives lambda2*.
    result.parallel = true;
    lambda1 = 0;
    lambda2 = (lambda1 * d1d2 + d2_p1p2) / d2d2;
  } else {
    lambda1 = (d2d2 * d1_p2p1 + d1d2 * d2_p1p2) / deno;  // Eq. 4-8
    lambda2 = (d1d2 * d1_p2p1 + d1d1 * d2_p1p2) / deno;  // Eq. 4-9
  }
  const Vec3<Scalar> p1_star = p1 + lambda1 * d1;  // Eq. 4-10
  const Vec3<Scalar> p2_star = p2 + lambda2 * d2;  // Eq. 4-11
  result.point = Scalar(0.5) * (p1_star + p2_star);  // Eq. 4-12
  result.gap = (p1_star - p2_star).norm();
  return result;
}

}  // namespace

template <typename Scalar>
ThesisExpansion<Scalar> expand_prism_as_thesis(const HullPoints& hull, double delta) {
  if (static_cast<int>(hull.points.size()) != kThesisPrismVertexCount) {
    throw std::invalid_argument("thesis expansion needs a 16-vertex prism, got " +
                                std::to_string(hull.points.size()) + " points");
  }
  if (!(delta > 0.0)) {
    throw std::invalid_argument("thesis expansion needs a positive tolerance");
  }
  // The thesis read its data as short floating numbers: round everything to Scalar first.
  std::array<Vec3<Scalar>, kThesisPrismVertexCount> p;
  for (int k = 0; k < kThesisPrismVertexCount; ++k) {
    p[k] = hull.points[k].template cast<Scalar>();
  }
  const Scalar delta_s = static_cast<Scalar>(delta);
  const std::array<Vec3<Scalar>, 2> cap_normals = {newell_normal(p, 0),
                                                   newell_normal(p, kCapSize)};
  for (const auto& normal : cap_normals) {
    if (!(normal.norm() > Scalar(0))) {
      throw std::invalid_argument("thesis expansion: a cap has no normal (collinear points)");
    }
  }

  ThesisExpansion<Scalar> result;
  // lines[k]: parallel line of the cap edge from vertex k-1 to vertex k (P2 = k-1, P3 = k).
  std::array<OffsetLine<Scalar>, kThesisPrismVertexCount> lines;
  for (int k = 0; k < kThesisPrismVertexCount; ++k) {
    const int i2 = cap_neighbour(k, -1);
    const int i1 = cap_neighbour(k, -2);
    const int i4 = cap_neighbour(k, +1);
    const auto& normal = cap_normals[k < kCapSize ? 0 : 1];
    const EdgeOffsetResult<Scalar> edge =
        offset_edge(p[i1], p[i2], p[k], p[i4], p[partner(k)], normal, delta_s);
    lines[k] = edge.line;
    result.origin_on_cap_plane += edge.origin_on_plane ? 1 : 0;
    result.degenerate_in_plane_sign += edge.degenerate_in_plane_sign ? 1 : 0;
    result.in_plane_minus += edge.in_plane_minus ? 1 : 0;
  }
  for (int k = 0; k < kThesisPrismVertexCount; ++k) {
    // Vertex k joins edge (k-1, k) [base built at k] and edge (k, k+1) [base built at k+1].
    const Midpoint<Scalar> m = closest_midpoint(lines[k], lines[cap_neighbour(k, +1)]);
    result.vertices[k] = m.point;
    result.midpoint_gaps[k] = m.gap;
    result.parallel_lines[k] = m.parallel;
    if (m.gap > result.max_midpoint_gap) result.max_midpoint_gap = m.gap;
  }
  return result;
}

template ThesisExpansion<float> expand_prism_as_thesis<float>(const HullPoints&, double);
template ThesisExpansion<double> expand_prism_as_thesis<double>(const HullPoints&, double);

}  // namespace grpvss::geometry
