#pragma once
/// \file
/// \brief Two rounded-up inputs of the axis-radius bound (proofs/motion-bound.md#lemma-axis-radius)
/// that the verifier's upward double evaluation and the checker's exact one share.

#include "grpvss/model/hull_points.hpp"

namespace grpvss::geometry {

/// An upper bound on |sin alpha| or |cos alpha| from libm's value `computed`:
/// min(1, |computed| + 2^-51) rounded up (proofs/fk-rounding.md#trig-rounding).
double trig_magnitude_upper(double computed);

/// An upper bound on max sqrt(x^2 + y^2) over the hull's points (the distance from the link
/// frame's z axis), evaluated with upward rounding. The exact evaluation re-checks it.
double radial_extent_upper(const HullPoints& hull);

}  // namespace grpvss::geometry
