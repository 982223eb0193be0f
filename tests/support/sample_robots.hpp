#pragma once
/// \file
/// \brief Robot models built in code for tests (independent of the io reader).

#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// IBM 7545 of thesis Appendix A.1.1.1 (DH, limits, acc/dec as in data/ibm7545/robot.txt),
/// with one simple box hull per link.
RobotModel make_ibm7545_model();

/// The PUMA 560-style 6-axis arm of data/puma560/robot.txt (DH, limits), one box hull per link.
RobotModel make_puma560_model();

}  // namespace grpvss::test
