#include "support/rounding_reference.hpp"

#include <CGAL/Gmpq.h>

#include <array>
#include <cmath>
#include <limits>

namespace grpvss::testing {

namespace {

using Q = CGAL::Gmpq;
using Q3 = std::array<Q, 3>;

Q3 lift(const Eigen::Vector3d& v) { return {Q(v.x()), Q(v.y()), Q(v.z())}; }

/// n = (f1 - f0) x (f2 - f0).
Q3 plane_normal(const Q3& o, const Q3& a, const Q3& b) {
  Q3 u, w;
  for (int k = 0; k < 3; ++k) {
    u[k] = a[k] - o[k];
    w[k] = b[k] - o[k];
  }
  return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

Q side(const Q3& n, const Q3& o, const Q3& x) {
  return n[0] * (x[0] - o[0]) + n[1] * (x[1] - o[1]) + n[2] * (x[2] - o[2]);
}

}  // namespace

double reference_round(const Q& x) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double q = CGAL::to_double(x);
  for (;;) {
    const double below = std::nextafter(q, -kInf);
    const double above = std::nextafter(q, kInf);
    if (x < (Q(q) + Q(below)) / 2) {
      q = below;
    } else if (!(x < (Q(q) + Q(above)) / 2)) {
      q = above;
    } else {
      return q;
    }
  }
}

int reference_plane_side(const Eigen::Vector3d& x, const Eigen::Vector3d& f0,
                         const Eigen::Vector3d& f1, const Eigen::Vector3d& f2) {
  const Q3 o = lift(f0);
  return static_cast<int>(CGAL::sign(side(plane_normal(o, lift(f1), lift(f2)), o, lift(x))));
}

Eigen::Vector3d reference_crossing(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                   const Eigen::Vector3d& f0, const Eigen::Vector3d& f1,
                                   const Eigen::Vector3d& f2) {
  const Q3 o = lift(f0), P = lift(p), R = lift(q);
  const Q3 n = plane_normal(o, lift(f1), lift(f2));
  const Q s_p = side(n, o, P), s_q = side(n, o, R);
  const Q t = s_p / (s_p - s_q);
  Eigen::Vector3d rounded;
  for (int k = 0; k < 3; ++k) rounded[k] = reference_round(P[k] + t * (R[k] - P[k]));
  return rounded;
}

}  // namespace grpvss::testing
