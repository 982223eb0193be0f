#pragma once
// Exact numbers a + b sqrt(d) (a, b, d rational, d >= 0): the roots of a quadratic with
// rational coefficients and polynomials evaluated there, with an exact sign.
// proof: proofs/joint-variation.md#lemma-position-limits
#include <cmath>
#include <optional>

#include <gmpxx.h>

namespace grpvss::motion::detail {

/// The double nearest to x (mpq_class::get_d truncates).
inline double nearest_double(const mpq_class& x) {
  const double truncated = x.get_d();
  double best = truncated;
  for (const double candidate : {std::nextafter(truncated, -HUGE_VAL), std::nextafter(truncated, HUGE_VAL)}) {
    if (abs(mpq_class(candidate) - x) < abs(mpq_class(best) - x)) best = candidate;
  }
  return best;
}

/// sqrt(x) when it is rational.
inline std::optional<mpq_class> rational_square_root(const mpq_class& x) {
  if (sgn(x) < 0 || !mpz_perfect_square_p(x.get_num_mpz_t()) ||
      !mpz_perfect_square_p(x.get_den_mpz_t())) {
    return std::nullopt;
  }
  mpz_class num, den;
  mpz_sqrt(num.get_mpz_t(), x.get_num_mpz_t());
  mpz_sqrt(den.get_mpz_t(), x.get_den_mpz_t());
  return mpq_class(num, den);
}

struct QuadraticSurd {
  mpq_class a, b, d;  ///< a + b sqrt(d); every operand of one computation shares d

  static QuadraticSurd rational(const mpq_class& x, const mpq_class& d) { return {x, 0, d}; }
  /// A double near the value, for messages only: the nearest one when the value is rational.
  double approximate() const {
    if (sgn(b) == 0) return nearest_double(a);
    if (const auto root = rational_square_root(d)) return nearest_double(a + b * *root);
    return a.get_d() + b.get_d() * std::sqrt(d.get_d());
  }
};

inline QuadraticSurd operator+(const QuadraticSurd& x, const QuadraticSurd& y) {
  return {x.a + y.a, x.b + y.b, x.d};
}
inline QuadraticSurd operator-(const QuadraticSurd& x, const QuadraticSurd& y) {
  return {x.a - y.a, x.b - y.b, x.d};
}
inline QuadraticSurd operator*(const QuadraticSurd& x, const QuadraticSurd& y) {
  return {x.a * y.a + x.b * y.b * x.d, x.a * y.b + x.b * y.a, x.d};
}

/// -1, 0 or +1: the sign of a + b sqrt(d), exactly. When a and b sqrt(d) have opposite
/// signs, the sign is the one of the larger magnitude, found by comparing squares.
inline int sign(const QuadraticSurd& x) {
  const int sa = sgn(x.a);
  const int sb = (x.d == 0) ? 0 : sgn(x.b);
  if (sb == 0) return sa;
  if (sa == 0 || sa == sb) return sb;
  const int larger = sgn(x.a * x.a - x.b * x.b * x.d);  // > 0: |a| wins
  return larger == 0 ? 0 : (larger > 0 ? sa : sb);
}

}  // namespace grpvss::motion::detail
