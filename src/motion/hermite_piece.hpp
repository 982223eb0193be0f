#pragma once
// One piece of a joint's interpolation in its normalised parameter s = (t - t_k) / h,
// h = t_{k+1} - t_k, and the total-variation bound of proofs/joint-variation.md, written once
// for two number types: detail::Interval (the verifier, enclosures of exact values) and
// mpq_class (the checker, exact). The same recursion (same splits, same depth) for both is
// what makes the rounded bound never smaller than the exact one
// (proofs/joint-variation.md#rounded-evaluation).
#include <Eigen/Core>

namespace grpvss::motion::detail {

/// Deepest midpoint subdivision of a piece whose derivative changes sign
/// (proofs/joint-variation.md#theorem-piece-variation).
inline constexpr int kMaxSplitDepth = 6;

/// q(s) = c0 + c1 s + c2 s^2 + c3 s^3 on s in [0, 1]; `linear` when c2 = c3 = 0 by
/// construction (joint-linear interpolation).
template <class Number>
struct PiecePolynomial {
  Number c0, c1, c2, c3;
  bool linear = false;

  Number value(const Number& s) const { return c0 + s * (c1 + s * (c2 + s * c3)); }
  /// dq/ds (= h dq/dt).
  Number slope(const Number& s) const {
    const Number two_c2 = c2 + c2;
    const Number three_c3 = c3 + c3 + c3;
    return c1 + s * (two_c2 + s * three_c3);
  }
};

/// The power-basis coefficients from the waypoint data (h = t_{k+1} - t_k, p, m in per-second
/// units): c1 = h m0, c2 = 3(p1 - p0) - 2 h m0 - h m1, c3 = 2(p0 - p1) + h m0 + h m1
/// (cubic Hermite); c1 = p1 - p0 (linear).
template <class Number>
PiecePolynomial<Number> hermite_polynomial(const Number& h, const Number& p0, const Number& p1,
                                           const Number& m0, const Number& m1) {
  const Number h_m0 = h * m0, h_m1 = h * m1;
  const Number rise = p1 - p0;
  PiecePolynomial<Number> piece;
  piece.c0 = p0;
  piece.c1 = h_m0;
  piece.c2 = rise + rise + rise - h_m0 - h_m0 - h_m1;
  piece.c3 = h_m0 + h_m1 - rise - rise;
  return piece;
}
template <class Number>
PiecePolynomial<Number> linear_polynomial(const Number& p0, const Number& p1) {
  PiecePolynomial<Number> piece;
  piece.c0 = p0;
  piece.c1 = p1 - p0;
  piece.c2 = p0 - p0;
  piece.c3 = p0 - p0;
  piece.linear = true;
  return piece;
}

/// One end of a sub-interval: the parameter, the value and dq/ds there.
template <class Number>
struct PieceEnd {
  Number s, q, slope;
};

template <class Number>
PieceEnd<Number> evaluate_end(const PiecePolynomial<Number>& piece, const Number& s) {
  return {s, piece.value(s), piece.slope(s)};
}

/// An upper bound of the total variation of q on [a.s, b.s] (a.s < b.s):
/// |q(b) - q(a)| when the Bezier derivative test proves q monotone there, else the sum over
/// the two halves, and at the deepest level the control-polygon variation.
/// `Arithmetic` supplies: Bound, magnitude(Number) -> Bound, sum(Bound, Bound) -> Bound,
/// third(Number), midpoint(Number, Number), monotone(d0, d1, d2) -> bool.
/// proof: proofs/joint-variation.md#theorem-piece-variation
template <class Arithmetic, class Number>
typename Arithmetic::Bound piece_variation(const PiecePolynomial<Number>& piece,
                                           const PieceEnd<Number>& a, const PieceEnd<Number>& b,
                                           int depth = 0) {
  const Number rise = b.q - a.q;
  if (piece.linear) return Arithmetic::magnitude(rise);
  const Number width = b.s - a.s;
  // proof: proofs/joint-variation.md#lemma-bezier-form
  const Number d0 = Arithmetic::third(width * a.slope);
  const Number d2 = Arithmetic::third(width * b.slope);
  const Number d1 = rise - d0 - d2;
  // proof: proofs/joint-variation.md#lemma-monotone-test
  if (Arithmetic::monotone(d0, d1, d2)) return Arithmetic::magnitude(rise);
  if (depth == kMaxSplitDepth) {
    // proof: proofs/joint-variation.md#lemma-control-polygon
    return Arithmetic::sum(Arithmetic::sum(Arithmetic::magnitude(d0), Arithmetic::magnitude(d1)),
                           Arithmetic::magnitude(d2));
  }
  const PieceEnd<Number> middle = evaluate_end(piece, Arithmetic::midpoint(a.s, b.s));
  return Arithmetic::sum(piece_variation<Arithmetic>(piece, a, middle, depth + 1),
                         piece_variation<Arithmetic>(piece, middle, b, depth + 1));
}

}  // namespace grpvss::motion::detail
