// The checker's exact numbers: GMP rationals, and a double taken exactly (every finite double
// is a rational, so nothing is rounded).
#pragma once

#include <gmpxx.h>

namespace grpvss::certify {

using Rational = mpq_class;

inline Rational exact(double value) { return Rational(value); }

}  // namespace grpvss::certify
