#pragma once
// A VerificationResult built by hand to mirror every step the thesis prints in its output
// sample (Appendix A.3), in library units (radians for revolute joints).

#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// Joint types of the IBM 7545: revolute, revolute, prismatic, revolute (thesis A.1.1.1).
std::vector<JointType> ibm7545_joint_types();

/// A RobotModel with the IBM 7545's joint types (no hulls, no DH data: reports need types only).
RobotModel ibm7545_joint_type_model();

/// Steps 1-4, 33-36, 40-47, 82-83 of A.3 (all it prints), segments 1-4, error 3 in segment 4.
certify::VerificationResult thesis_a3_sample_result();

/// Degrees -> radians for a value of joint `joint` (0-based) of the IBM 7545.
double ibm7545_library_value(int joint, double file_value);

}  // namespace grpvss::test
