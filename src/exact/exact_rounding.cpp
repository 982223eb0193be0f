/// \file
/// \brief Rounding the exact core's rational points to doubles (exact_rounding.hpp).
/// Only CGAL's Mpzf and Interval_nt are used here: no kernel.

#include "exact_rounding.hpp"
#include "extended_precision.hpp"

#include <CGAL/Gmpq.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <cfenv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace grpvss::geometry {

namespace {

using Fast = CGAL::Mpzf;

/// A first guess within a few ulps of num / den (den > 0).
double quotient_estimate(const Fast& num, const Fast& den) {
  const double q = CGAL::to_double(num) / CGAL::to_double(den);
  if (std::isfinite(q)) return q;
  return CGAL::to_double(CGAL::Gmpq(static_cast<CGAL::Gmpq>(num)) / static_cast<CGAL::Gmpq>(den));
}

double round_by_midpoints_from(const Fast& num, const Fast& den, double q) {
  const double inf = std::numeric_limits<double>::infinity();
  const Fast twice_num = num + num;
  for (int step = 0; step < 64; ++step) {
    const double below = std::nextafter(q, -inf);
    const double above = std::nextafter(q, inf);
    if (twice_num < (Fast(q) + Fast(below)) * den) {
      q = below;
    } else if (!(twice_num < (Fast(q) + Fast(above)) * den)) {
      q = above;
    } else {
      return q;
    }
  }
  throw std::logic_error("round_quotient_by_midpoints did not converge");
}

}  // namespace

double round_quotient_by_midpoints(const Fast& num, const Fast& den) {
  // q is the answer iff (q + prev(q)) / 2 <= num / den < (q + next(q)) / 2 (den > 0),
  // tested by cross-multiplying.
  if (CGAL::is_zero(num)) return 0.0;
  return round_by_midpoints_from(num, den, quotient_estimate(num, den));
}

double round_quotient_to_nearest(const Fast& num, const Fast& den) {
  // proof: proofs/interference.md#rounding-the-points
  if (CGAL::is_zero(num)) return 0.0;
  const double inf = std::numeric_limits<double>::infinity();
  double q = quotient_estimate(num, den);
  // The half gaps below are exact while q is normal and far from overflow (q - prev(q) is
  // exact by Sterbenz and a power of two); elsewhere only the midpoint comparisons are used.
  constexpr double kFilterRange = 0x1p-900;
  using Enclosure = CGAL::Interval_nt<>;  // protected: sets its own rounding per operation
  const Enclosure den_enclosure(CGAL::to_interval(den));
  for (int step = 0; step < 4 && std::abs(q) > kFilterRange && std::abs(q) < 1.0 / kFilterRange;
       ++step) {
    const Fast residual = num - Fast(q) * den;  // exact
    if (CGAL::is_zero(residual)) return q;
    const double half_gap_below = 0.5 * (q - std::nextafter(q, -inf));
    const double half_gap_above = 0.5 * (std::nextafter(q, inf) - q);
    const Enclosure offset = Enclosure(CGAL::to_interval(residual)) / den_enclosure;
    if (offset.inf() >= -half_gap_below && offset.sup() < half_gap_above) return q;
    if (offset.sup() < -half_gap_below) {
      q = std::nextafter(q, -inf);
    } else if (offset.inf() >= half_gap_above) {
      q = std::nextafter(q, inf);
    } else {
      break;  // num / den within the enclosure's width of a midpoint
    }
  }
  return round_by_midpoints_from(num, den, q);
}

std::optional<Eigen::Vector3d> crossing_rounded_by_error_bound(const Eigen::Vector3d& p,
                                                               const Eigen::Vector3d& q,
                                                               const Eigen::Vector3d& f0,
                                                               const Eigen::Vector3d& f1,
                                                               const Eigen::Vector3d& f2) {
  // proof: proofs/interference.md#crossing-by-error-bound. Every operation below is one
  // round-to-nearest long double operation (relative error <= u, no underflow: degree <= 4
  // in doubles stays far inside long double's exponent range). Each bound E is the lemma's
  // first-order term times (1 + 2^-40), which covers the rounding of the bound's own
  // evaluation and the lemma's higher-order terms.
  using L = long double;
  if constexpr (std::numeric_limits<L>::digits < 64) {
    return std::nullopt;
  } else {
    if (!extended_precision_rounds_to_nearest()) return std::nullopt;  // the lemma's rounding
    constexpr L u = 0x1p-64L;
    const auto abs = [](L x) { return x < 0 ? -x : x; };
    const L ax = L(f1.x()) - L(f0.x()), ay = L(f1.y()) - L(f0.y()), az = L(f1.z()) - L(f0.z());
    const L bx = L(f2.x()) - L(f0.x()), by = L(f2.y()) - L(f0.y()), bz = L(f2.z()) - L(f0.z());
    // n = a x b and its permanent N = |a_y b_z| + |a_z b_y|, ...
    const L aybz = ay * bz, azby = az * by, azbx = az * bx, axbz = ax * bz, axby = ax * by,
            aybx = ay * bx;
    const L nx = aybz - azby, ny = azbx - axbz, nz = axby - aybx;
    const L Nx = abs(aybz) + abs(azby), Ny = abs(azbx) + abs(axbz), Nz = abs(axby) + abs(aybx);
    constexpr L inflate = 1 + 0x1p-40L;
    // s = n . (x - f0) with |s^ - s| <= gamma_8 S, S = N . |x - f0| <= S^ (1 + 9u).
    const auto side = [&](const Eigen::Vector3d& x, L& bound) {
      const L cx = L(x.x()) - L(f0.x()), cy = L(x.y()) - L(f0.y()), cz = L(x.z()) - L(f0.z());
      bound = 8 * u * (Nx * abs(cx) + Ny * abs(cy) + Nz * abs(cz)) * inflate;
      return nx * cx + ny * cy + nz * cz;
    };
    L error_p = 0, error_q = 0;
    const L s_p = side(p, error_p);
    const L s_q = side(q, error_q);
    const L d = s_p - s_q;  // exactly |s_p| + |s_q| > 0 in magnitude: opposite signs
    const L error_d = (error_p + error_q + u * abs(d)) * inflate;
    if (!(abs(d) > 4 * error_d)) return std::nullopt;
    const L t = s_p / d;  // the exact t is in [0, 1]; |t^| < 1.5
    const L error_t = ((error_p + error_d) / abs(d) + 1.6L * u) * inflate;
    Eigen::Vector3d rounded;
    for (int k = 0; k < 3; ++k) {
      if (p[k] == q[k]) {  // X_k = p_k exactly
        rounded[k] = p[k];
        continue;
      }
      const L step = L(q[k]) - L(p[k]);
      const L x = L(p[k]) + t * step;
      const L error_x = (error_t * abs(step) + 2.1L * u * abs(t) * abs(step) + u * abs(x)) * inflate;
      const double nearest = static_cast<double>(x);  // round to nearest (ties to even)
      if (!(std::abs(nearest) > 0x1p-1000 && std::abs(nearest) < 0x1p1000)) return std::nullopt;
      const L below = std::nextafter(nearest, -std::numeric_limits<double>::infinity());
      const L above = std::nextafter(nearest, std::numeric_limits<double>::infinity());
      const L midpoint_below = (L(nearest) + below) / 2;  // exact: 55 bits at most
      const L midpoint_above = (L(nearest) + above) / 2;
      // x lies between the two midpoints; the differences are exact (Sterbenz).
      if (!(x - midpoint_below > error_x && midpoint_above - x > error_x)) return std::nullopt;
      rounded[k] = nearest;
    }
    return rounded;
  }
}

}  // namespace grpvss::geometry
