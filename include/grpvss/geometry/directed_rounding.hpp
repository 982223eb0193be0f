#pragma once
/// \file
/// \brief Directed (upward) rounding scope and the few rounded operations the certified fast
/// path needs: sums, products, quotients and square roots rounded up or down.
///
/// All operations assume an active UpwardRoundingScope. Rounding down is obtained from
/// rounding up by negation, \f$\mathrm{RD}(x \circ y) = -\mathrm{RU}(-(x \circ y))\f$, which
/// IEEE 754 makes exact because negation never rounds. The only exception is the square root:
/// \f$\mathrm{pred}(\mathrm{RU}(\sqrt{x})) < \sqrt{x}\f$ because RU returns the smallest double
/// not below the true value.
///
/// Why the asm barriers: GCC may move or constant-fold floating-point arithmetic across a
/// call to std::fesetround even with -frounding-math (GCC bug 34678). Every operand and every
/// result passes through an `asm volatile` that the compiler must keep in program order
/// with the scope's own barriers, so each operation is evaluated while upward rounding is in
/// force. proof: proofs/fast-path.md#directed-rounding

#include <cfenv>
#if defined(__x86_64__) && defined(__SSE2__)
#include <xmmintrin.h>
#endif
#include <cmath>
#include <limits>

#include "grpvss/common/next_double.hpp"

namespace grpvss::geometry::rounding {

/// \brief Forces \p x to be materialised here, in program order with other barriers.
inline double barrier(double x) {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__)) && defined(__SSE2__)
  asm volatile("" : "+x"(x));
#elif defined(__GNUC__)
  asm volatile("" : "+g"(x));
#else
  volatile double v = x;
  x = v;
#endif
  return x;
}

/// \brief RAII: switches the FPU to round-toward-+infinity, restores the previous mode on exit.
///
/// On x86-64 all double arithmetic is SSE2, whose rounding is the MXCSR RC field (bits
/// 13-14; 10 = toward +infinity): setting it directly costs a few cycles, where glibc's
/// std::fesetround also rewrites the x87 control word and was ~10% of a certified CP
/// operation. Elsewhere the portable std::fesetround.
class UpwardRoundingScope {
 public:
#if defined(__x86_64__) && defined(__SSE2__)
  UpwardRoundingScope() : previous_(_mm_getcsr()) {
    _mm_setcsr((previous_ & ~kRoundingBits) | kRoundUp);
    asm volatile("" ::: "memory");
  }
  ~UpwardRoundingScope() {
    asm volatile("" ::: "memory");
    _mm_setcsr(previous_);
  }
#else
  UpwardRoundingScope() : previous_(std::fegetround()) {
    std::fesetround(FE_UPWARD);
    asm volatile("" ::: "memory");
  }
  ~UpwardRoundingScope() {
    asm volatile("" ::: "memory");
    std::fesetround(previous_);
  }
#endif
  UpwardRoundingScope(const UpwardRoundingScope&) = delete;
  UpwardRoundingScope& operator=(const UpwardRoundingScope&) = delete;

 private:
#if defined(__x86_64__) && defined(__SSE2__)
  static constexpr unsigned kRoundingBits = 0x6000u;
  static constexpr unsigned kRoundUp = 0x4000u;
  unsigned previous_;
#else
  int previous_;
#endif
};

// --- upward-rounded primitives (require an active UpwardRoundingScope) ---
inline double add_up(double a, double b) { return barrier(barrier(a) + barrier(b)); }
inline double sub_up(double a, double b) { return barrier(barrier(a) - barrier(b)); }
inline double mul_up(double a, double b) { return barrier(barrier(a) * barrier(b)); }
inline double div_up(double a, double b) { return barrier(barrier(a) / barrier(b)); }
inline double sqrt_up(double a) { return barrier(std::sqrt(barrier(a))); }

// --- downward-rounded primitives via negation ---
inline double add_down(double a, double b) { return -add_up(-a, -b); }
inline double sub_down(double a, double b) { return -sub_up(b, a); }
inline double mul_down(double a, double b) { return -mul_up(-a, b); }
inline double div_down(double a, double b) { return -div_up(-a, b); }
/// \brief A double not above \f$\sqrt{a}\f$ (\p a >= 0).
inline double sqrt_down(double a) {
  if (!(a > 0.0)) return 0.0;
  return next_toward_zero(sqrt_up(a));
}

/// \brief Upper bound of \f$\lvert x\rvert^2\f$ given \f$x \in [lo, hi]\f$.
inline double square_up_of_range(double lo, double hi) {
  const double m = std::fmax(std::fabs(lo), std::fabs(hi));
  return mul_up(m, m);
}
/// \brief Lower bound of \f$\lvert x\rvert^2\f$ given \f$x \in [lo, hi]\f$ (0 if the range
/// contains 0).
inline double square_down_of_range(double lo, double hi) {
  if (lo <= 0.0 && hi >= 0.0) return 0.0;
  const double m = std::fmin(std::fabs(lo), std::fabs(hi));
  return mul_down(m, m);
}

/// \brief Upper bound of the dot product \f$n \cdot p\f$ (upward rounding throughout).
///
/// Monotonicity of RU makes every partial result an upper bound of the exact partial result.
inline double dot_up(const double* n, const double* p) {
  return add_up(add_up(mul_up(n[0], p[0]), mul_up(n[1], p[1])), mul_up(n[2], p[2]));
}
/// \brief Lower bound of the dot product \f$n \cdot p\f$.
inline double dot_down(const double* n, const double* p) {
  const double m[3] = {-n[0], -n[1], -n[2]};
  return -dot_up(m, p);
}

// --- directed sums WITHOUT a scope (round-to-nearest mode, the default) ---
// Switching the rounding mode costs two std::fesetround calls, which dominated the verifier's
// per-step radius arithmetic. A sum's rounding error is exactly representable (Knuth's
// TwoSum), so the sum rounded down / up is the nearest sum moved one ulp when the error has
// the wrong sign: bit-identical to add_down / add_up under a scope.
// proof: proofs/fast-path.md#directed-rounding

/// \brief \f$\mathrm{RD}(a + b)\f$ computed in round-to-nearest mode (no scope may be
/// active). Falls back to a scope when the sum overflows.
inline double nearest_mode_add_down(double a, double b) {
  const double s = barrier(barrier(a) + barrier(b));
  if (!std::isfinite(s)) {
    UpwardRoundingScope upward;
    return add_down(a, b);
  }
  const double bb = barrier(s - a);
  const double error = barrier(barrier(a - barrier(s - bb)) + barrier(b - bb));
  return error < 0.0 ? next_down(s) : s;
}
/// \brief \f$\mathrm{RU}(a + b)\f$ in round-to-nearest mode (no scope may be active).
inline double nearest_mode_add_up(double a, double b) { return -nearest_mode_add_down(-a, -b); }
/// \brief \f$\mathrm{RD}(a - b)\f$ in round-to-nearest mode (no scope may be active).
inline double nearest_mode_sub_down(double a, double b) { return nearest_mode_add_down(a, -b); }

}  // namespace grpvss::geometry::rounding
