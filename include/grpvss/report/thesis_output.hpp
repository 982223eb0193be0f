#pragma once
/// \file
/// \brief The thesis's output file (Appendix A.3), rendered from a verification run.
///
/// Layout (docs/thesis-output.md): the tolerance line; in certified mode only, one added line
/// `THE RESOLUTION MODE = CERTIFIED` (thesis mode reproduces A.3 with nothing added); per
/// segment its header `THE kTH SEGMENT OF THE PATH INPUT FROM FILE <label>` and the
/// specification block of its kind; per step the joint values (degrees for revolute joints)
/// and the interference points (x, y, z, tab-separated); each error as the three-line thesis
/// block; then `TOTAL n STEPS IN THIS PATH` and `COLLISIONS DETECTED IN THIS PATH` or
/// `NO COLLISION DETECTED IN THIS PATH`. Numbers have 2 decimals, ordinals are `1TH`, `2TH`,
/// `3TH` as in the thesis.

#include <string>
#include <vector>

#include "grpvss/certify/verification_result.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::report {

/// \brief Renders `result` in the A.3 layout; `joint_types[i]` is the type of joint i+1
/// (revolute values and speeds are printed in degrees).
/// \throws std::logic_error if the result is inconsistent (a joint vector of the wrong size,
///         a step whose segment has no record, steps out of order).
std::string render_thesis_output(const certify::VerificationResult& result,
                                 const std::vector<JointType>& joint_types);

/// Same, with the joint types taken from `robot`.
std::string render_thesis_output(const certify::VerificationResult& result,
                                 const RobotModel& robot);

/// True when the thesis would print `COLLISIONS DETECTED IN THIS PATH`: some step has
/// interference points, an interfering expanded robot, or a colliding unexpanded robot.
bool thesis_reports_collision(const certify::VerificationResult& result);

/// The n of `TOTAL n STEPS IN THIS PATH`: the index of the last step (steps are numbered
/// 1, 2, ... over the whole path), 0 without steps.
/// \throws std::logic_error if the step indices do not increase.
int total_steps(const certify::VerificationResult& result);

}  // namespace grpvss::report
