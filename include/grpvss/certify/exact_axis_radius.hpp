#pragma once
/// \file
/// \brief R_{jh} of proofs/motion-bound.md#lemma-axis-radius in exact rational arithmetic:
/// the certificate checker's reference, against which the verifier's rounded-up
/// HullRadiusTable is tested. Also the two rounded inputs both evaluations share (so that
/// the verifier's upward double evaluation is never below the checker's exact one).

#include <gmpxx.h>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// An upper bound on |sin alpha| or |cos alpha| from libm's value `computed`:
/// min(1, |computed| + 2^-51) rounded up (proofs/fk-rounding.md#trig-rounding).
double trig_magnitude_upper(double computed);

/// An upper bound on max sqrt(x^2 + y^2) over the hull's points (the distance from the link
/// frame's z axis), evaluated with upward rounding. The exact evaluation re-checks it.
double radial_extent_upper(const HullPoints& hull);

/// The radial/axial recursion of proofs/motion-bound.md#lemma-axis-radius, exactly, for hull
/// `hull` of link `link` about the axis of joint `joint` (1 <= joint <= link). Never above
/// the absolute-sum bound |a_j| + sum_{m=j+1}^{i}(|a_m| + d^max_m) + max |v|_1.
mpq_class exact_axis_radius(const RobotModel& robot, int link, const HullPoints& hull, int joint);

}  // namespace grpvss::certify
