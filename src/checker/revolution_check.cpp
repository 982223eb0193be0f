#include "revolution_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "checked_cell.hpp"

namespace grpvss::certify {
namespace {

using Vector3q = std::array<Rational, 3>;

Vector3q exact3(const Eigen::Vector3d& v) { return {exact(v[0]), exact(v[1]), exact(v[2])}; }

Rational dot(const Vector3q& a, const Vector3q& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

struct ExactRing {
  Rational axial, radius;
};

// F(s) for s in [s_1, s_k]: the rings' piecewise-linear interpolation.
Rational profile_at(const std::vector<ExactRing>& rings, const Rational& s) {
  for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
    if (s <= rings[i + 1].axial) {
      const Rational t = (s - rings[i].axial) / (rings[i + 1].axial - rings[i].axial);
      return rings[i].radius + t * (rings[i + 1].radius - rings[i].radius);
    }
  }
  return rings.back().radius;
}

// min F over [lo, hi] (inside [s_1, s_k]): at an end or at a ring between (F is piecewise linear).
Rational profile_minimum(const std::vector<ExactRing>& rings, const Rational& lo, const Rational& hi) {
  Rational smallest = std::min(profile_at(rings, lo), profile_at(rings, hi));
  for (const ExactRing& ring : rings) {
    if (lo < ring.axial && ring.axial < hi) smallest = std::min(smallest, ring.radius);
  }
  return smallest;
}

}  // namespace

// proof: proofs/two-ball-cover.md#revolution-solid
bool solid_encloses_exactly(const geometry::RevolutionSolid& solid,
                            const std::vector<Eigen::Vector3d>& raw_L,
                            const geometry::JointAxisLine_L& axis, double hull_point_error) {
  if (solid.axis_point_L != axis.point_L || solid.axis_L != axis.direction_L) return false;
  if (solid.rings.empty() || raw_L.empty()) return false;
  const Vector3q p = exact3(solid.axis_point_L);
  const Vector3q u = exact3(solid.axis_L);
  if (dot(u, u) != 1) return false;
  std::vector<ExactRing> rings;
  Rational largest_radius = 0, largest_axial = 0;
  for (const geometry::RevolutionRing& ring : solid.rings) {
    rings.push_back({exact(ring.axial), exact(ring.radius)});
    if (rings.back().radius < 0) return false;
    if (rings.size() >= 2 && !(rings[rings.size() - 2].axial < rings.back().axial)) return false;
    largest_radius = std::max(largest_radius, rings.back().radius);
    largest_axial = std::max(largest_axial, Rational(abs(rings.back().axial)));
  }
  // F concave: (V) at the vertices then holds on the whole hull (its set is convex).
  for (std::size_t i = 1; i + 1 < rings.size(); ++i) {
    const ExactRing& o = rings[i - 1];
    const ExactRing& a = rings[i];
    const ExactRing& q = rings[i + 1];
    if ((a.axial - o.axial) * (q.radius - o.radius) - (a.radius - o.radius) * (q.axial - o.axial) > 0) {
      return false;
    }
  }
  const Rational reach = largest_radius + largest_axial;
  const Rational delta = exact(axis.point_error) + 4 * exact(axis.direction_error) * reach;
  const Rational margin = exact(hull_point_error) + 2 * delta;
  for (const Eigen::Vector3d& h : raw_L) {
    const Vector3q hq = exact3(h);
    const Vector3q d = {hq[0] - p[0], hq[1] - p[1], hq[2] - p[2]};
    const Rational s = dot(d, u);
    const Rational lo = s - margin;
    const Rational hi = s + margin;
    if (lo < rings.front().axial || hi > rings.back().axial) return false;
    const Rational room = profile_minimum(rings, lo, hi) - margin;
    if (room < 0 || dot(d, d) - s * s > room * room) return false;
  }
  return true;
}

// max over S of m.c = m.p + max_i (s_i (m.u) + rho_i sqrt(|m|^2 - (m.u)^2)), m = R^T n; the
// claim rho_i sqrt(P) + lambda sqrt(Q) <= K_i is decided by squaring twice, for every ring.
// proof: proofs/two-ball-cover.md#revolution-solid-support
bool solid_side_holds_exactly(const geometry::RevolutionSolid& solid, const Eigen::Isometry3d& X_WL,
                              const geometry::SeparationWitness& witness, double lambda) {
  // Non-finite numbers have no rational value (a certificate may carry 1e999).
  const bool finite = std::isfinite(lambda) && std::isfinite(witness.offset_b) &&
                      witness.normal.allFinite() && X_WL.matrix().allFinite();
  if (!finite || !(lambda >= 0.0) || solid.rings.empty()) return false;
  const Vector3q n = exact3(witness.normal);
  const auto& X = X_WL.matrix();
  Vector3q m;
  for (int k = 0; k < 3; ++k) {
    m[static_cast<std::size_t>(k)] = exact(X(0, k)) * n[0] + exact(X(1, k)) * n[1] + exact(X(2, k)) * n[2];
  }
  const Vector3q t = {exact(X(0, 3)), exact(X(1, 3)), exact(X(2, 3))};
  const Rational along = dot(m, exact3(solid.axis_L));
  const Rational fixed = dot(n, t) + dot(m, exact3(solid.axis_point_L));
  const Rational across = dot(m, m) - along * along;  // P (|u| = 1)
  const Rational normal = dot(n, n);                  // Q
  const Rational claimed = exact(lambda);
  for (const geometry::RevolutionRing& ring : solid.rings) {
    const Rational radius = exact(ring.radius);
    if (radius < 0) return false;
    const Rational room = exact(witness.offset_b) - fixed - exact(ring.axial) * along;  // K_i
    if (room < 0) return false;
    const Rational rest = room * room - radius * radius * across - claimed * claimed * normal;
    if (rest < 0) return false;
    if (4 * radius * radius * claimed * claimed * across * normal > rest * rest) return false;
  }
  return true;
}

}  // namespace grpvss::certify
