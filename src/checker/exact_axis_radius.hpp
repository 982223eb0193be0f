#pragma once
/// \file
/// \brief R_{jh} of proofs/motion-bound.md#lemma-axis-radius in exact rational arithmetic:
/// the certificate checker's reference, against which the verifier's rounded-up
/// HullRadiusTable is tested. Both evaluations start from the same rounded inputs
/// (geometry/rounded_bounds.hpp), so the verifier's upward double evaluation is never below
/// the checker's exact one.

#include <gmpxx.h>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// The radial/axial recursion of proofs/motion-bound.md#lemma-axis-radius, exactly, for hull
/// `hull` of link `link` about the axis of joint `joint` (1 <= joint <= link). Never above
/// the absolute-sum bound |a_j| + sum_{m=j+1}^{i}(|a_m| + d^max_m) + max |v|_1.
mpq_class exact_axis_radius(const RobotModel& robot, int link, const HullPoints& hull, int joint);

}  // namespace grpvss::certify
