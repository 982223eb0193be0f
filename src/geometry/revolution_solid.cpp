#include "grpvss/geometry/revolution_solid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/placed_hull.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;
using namespace rounding;

constexpr double kPi = 3.14159265358979323846;
constexpr int kRoundnessDirections = 64;

/// The index k when u is exactly +-e_k, else -1: only then is |u| = 1 exactly.
int coordinate_axis(const Vector3d& u) {
  for (int k = 0; k < 3; ++k) {
    const bool others_zero = u[(k + 1) % 3] == 0.0 && u[(k + 2) % 3] == 0.0;
    if (others_zero && (u[k] == 1.0 || u[k] == -1.0)) return k;
  }
  return -1;
}

/// The smallest support of the points (relative to p) over directions across axis k.
double smallest_support_across(const std::vector<Vector3d>& points, const Vector3d& p, int k) {
  const Vector3d e1 = Vector3d::Unit((k + 1) % 3);
  const Vector3d e2 = Vector3d::Unit((k + 2) % 3);
  double smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kRoundnessDirections; ++i) {
    const double angle = 2.0 * kPi * i / kRoundnessDirections;
    const Vector3d d = std::cos(angle) * e1 + std::sin(angle) * e2;
    double support = -std::numeric_limits<double>::infinity();
    for (const Vector3d& h : points) support = std::max(support, (h - p).dot(d));
    smallest = std::min(smallest, support);
  }
  return smallest;
}

/// The upper concave envelope of (axial, radius) points: its vertices by increasing axial
/// coordinate (Andrew's monotone chain, upper half; at equal axial only the largest radius).
std::vector<RevolutionRing> upper_envelope(std::vector<RevolutionRing> points) {
  std::sort(points.begin(), points.end(), [](const RevolutionRing& a, const RevolutionRing& b) {
    return a.axial < b.axial || (a.axial == b.axial && a.radius > b.radius);
  });
  std::vector<RevolutionRing> hull;
  for (const RevolutionRing& q : points) {
    if (!hull.empty() && hull.back().axial == q.axial) continue;  // a lower radius, same axial
    while (hull.size() >= 2) {
      const RevolutionRing& o = hull[hull.size() - 2];
      const RevolutionRing& a = hull.back();
      const double cross = (a.axial - o.axial) * (q.radius - o.radius) -
                           (a.radius - o.radius) * (q.axial - o.axial);
      if (cross < 0.0) break;  // a turns clockwise: it stays on the upper envelope
      hull.pop_back();
    }
    hull.push_back(q);
  }
  return hull;
}

}  // namespace

double RevolutionSolid::largest_radius() const {
  double largest = 0.0;
  for (const RevolutionRing& ring : rings) largest = std::max(largest, ring.radius);
  return largest;
}

double RevolutionSolid::largest_abs_axial() const {
  double largest = 0.0;
  for (const RevolutionRing& ring : rings) largest = std::max(largest, std::fabs(ring.axial));
  return largest;
}

JointAxisLine_L joint_axis_line(const Eigen::Isometry3d& X_PJ, double rotation_error,
                                double translation_error) {
  JointAxisLine_L axis;
  axis.point_L = X_PJ.translation();
  axis.direction_L = X_PJ.linear().col(2);
  axis.point_error = translation_error;
  axis.direction_error = rotation_error;
  return axis;
}

// proof: proofs/two-ball-cover.md#revolution-solid
double revolution_margin_up(const JointAxisLine_L& axis, double hull_point_error, double reach) {
  UpwardRoundingScope upward;
  const double delta = add_up(axis.point_error, mul_up(mul_up(4.0, axis.direction_error), reach));
  return add_up(hull_point_error, mul_up(2.0, delta));
}

std::optional<RevolutionSolid> enclosing_revolution_solid(const std::vector<Vector3d>& raw_L,
                                                          const JointAxisLine_L& axis,
                                                          double hull_point_error) {
  const int k = coordinate_axis(axis.direction_L);
  if (raw_L.empty() || k < 0) return std::nullopt;
  const Vector3d& p = axis.point_L;
  const Vector3d& u = axis.direction_L;
  std::vector<RevolutionRing> profile;
  profile.reserve(raw_L.size());
  for (const Vector3d& h : raw_L) {
    const Vector3d d = h - p;
    const double s = d.dot(u);
    profile.push_back({s, (d - s * u).norm()});
  }
  const std::vector<RevolutionRing> envelope = upper_envelope(std::move(profile));
  RevolutionSolid solid;
  solid.axis_point_L = p;
  solid.axis_L = u;
  solid.rings = envelope;
  // Lambda must bound the result's largest radius + largest |axial|: twice the hull's, plus 1.
  const double reach = 2.0 * (solid.largest_radius() + solid.largest_abs_axial()) + 1.0;
  const double margin = revolution_margin_up(axis, hull_point_error, reach);
  if (!std::isfinite(reach) || !(margin <= 0.25)) return std::nullopt;
  // The evaluation above in double errs by a few ulps of these sizes; 1e-10 of them covers it
  // many times over (the checker decides the containment exactly anyway).
  const double dilation = margin + 1e-10 * (reach + p.cwiseAbs().maxCoeff()) + 1e-300;
  // Dilated by the square [-dilation, dilation]^2 in (axial, radius): each vertex moved both ways.
  std::vector<RevolutionRing> dilated;
  for (const RevolutionRing& ring : envelope) {
    dilated.push_back({ring.axial - dilation, ring.radius + dilation});
    dilated.push_back({ring.axial + dilation, ring.radius + dilation});
  }
  solid.rings = upper_envelope(std::move(dilated));
  if (smallest_support_across(raw_L, p, k) < kRevolutionRoundness * solid.largest_radius()) {
    return std::nullopt;
  }
  return solid;
}

double revolution_solid_extent(const RevolutionSolid& solid) {
  UpwardRoundingScope upward;
  double extent = 0.0;
  for (const RevolutionRing& ring : solid.rings) {
    for (int k = 0; k < 3; ++k) {
      const double along = mul_up(std::fabs(ring.axial), std::fabs(solid.axis_L[k]));
      extent = std::max(extent, add_up(add_up(std::fabs(solid.axis_point_L[k]), along), ring.radius));
    }
  }
  return extent;
}

// proof: proofs/two-ball-cover.md#revolution-solid-support
double placed_solid_support_upper(const RevolutionSolid& solid, const Eigen::Isometry3d& X_WL,
                                  const Vector3d& n) {
  UpwardRoundingScope upward;
  const auto& X = X_WL.matrix();
  // m = R^T n lies in [m_lo, m_lo + spread] componentwise; |m - m_lo|_2 <= spread.
  const RotatedNormal rotated = rotated_normal(X_WL, n);
  const Vector3d& m_lo = rotated.lower;
  const double spread = rotated.spread;
  const Vector3d& p = solid.axis_point_L;
  const Vector3d& u = solid.axis_L;
  const double translation[3] = {X(0, 3), X(1, 3), X(2, 3)};
  // n.t + m.p <= n.t + m_lo.p + spread |p|_inf.
  const double fixed = add_up(add_up(dot_up(n.data(), translation), dot_up(m_lo.data(), p.data())),
                              mul_up(spread, p.cwiseAbs().maxCoeff()));
  // m.u in [a_lo, a_hi]; s_i (m.u) is largest at an end.
  const double u_abs = u.cwiseAbs().maxCoeff();
  const double along_lo = dot_down(m_lo.data(), u.data());
  const double along_hi = dot_up(m_lo.data(), u.data());
  const double a_lo = sub_down(along_lo, mul_up(spread, u_abs));
  const double a_hi = add_up(along_hi, mul_up(spread, u_abs));
  // |m - (m.u) u| <= |m_lo - (m_lo.u) u| + spread (the projection is 1-Lipschitz), and
  // |m_lo - (m_lo.u) u|^2 = |m_lo|^2 - (m_lo.u)^2 as |u| = 1 exactly.
  const double across_squared =
      std::max(0.0, sub_up(dot_up(m_lo.data(), m_lo.data()), square_down_of_range(along_lo, along_hi)));
  const double across = add_up(sqrt_up(across_squared), spread);
  // S is the hull of its discs: its support is the largest of theirs.
  double largest = -std::numeric_limits<double>::infinity();
  for (const RevolutionRing& ring : solid.rings) {
    const double axial = std::max(mul_up(ring.axial, a_lo), mul_up(ring.axial, a_hi));
    largest = std::max(largest, add_up(axial, mul_up(ring.radius, across)));
  }
  const double bound = add_up(fixed, largest);
  return std::isfinite(bound) ? bound : std::numeric_limits<double>::infinity();
}

}  // namespace grpvss::geometry
