#pragma once
/// \file
/// \brief R_{jh} of proofs/motion-bound.md#lemma-axis-radius in exact rational arithmetic:
/// the certificate checker's reference, against which the verifier's rounded-up
/// HullRadiusTable is tested.

#include <gmpxx.h>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// \f$|a_j| + \sum_{m=j+1}^{i}(|a_m| + d^{\max}_m) + \max_{v \in h}\|v\|_1\f$, exactly, for
/// hull `hull` of link `link` about the axis of joint `joint` (1 <= joint <= link).
mpq_class exact_axis_radius(const RobotModel& robot, int link, const HullPoints& hull, int joint);

}  // namespace grpvss::certify
