#pragma once
/// \file
/// \brief The configuration of a 6R arm solution: the three binary choices that the closed
/// forms enumerate (2 x 2 x 2 = 8 branches), with their geometric meaning (docs/ik.md).

#include <ostream>
#include <string>

#include "grpvss/kinematics/opw_kinematics.hpp"
#include "grpvss/kinematics/ur_kinematics.hpp"

namespace grpvss::kinematics {

/// OPW: kFront / kBack - the wrist centre in front of / behind axis 1 (x of the axis-1 frame
/// >= 0 / < 0). UR: kRight / kLeft - looking from axis 1 along the horizontal reach toward the
/// wrist point P5, the arm's plane (offset d4 from axis 1) lies to the right / left.
enum class Shoulder { kFront, kBack, kLeft, kRight };

/// kUp: the elbow (axis 3) lies above the line from axis 2 to the wrist (OPW: the wrist centre;
/// UR: axis 4) in the arm plane, "above" seen with the reach pointing away from axis 1.
enum class Elbow { kUp, kDown };

/// OPW: kFlip when sin(theta_5) < 0, kNoFlip otherwise. UR: kDown when sin(theta_5) < 0, kUp
/// otherwise (theta_5: the model angle; = q5 for the KUKA, ABB and UR chains of docs/ik.md).
enum class Wrist { kNoFlip, kFlip, kUp, kDown };

struct ArmConfiguration {
  Shoulder shoulder = Shoulder::kFront;
  Elbow elbow = Elbow::kUp;
  Wrist wrist = Wrist::kNoFlip;
};

bool operator==(const ArmConfiguration& a, const ArmConfiguration& b);
bool operator!=(const ArmConfiguration& a, const ArmConfiguration& b);

/// "front, elbow up, no flip", "left, elbow down, wrist up", ...
std::string to_string(const ArmConfiguration& configuration);
std::ostream& operator<<(std::ostream& out, const ArmConfiguration& configuration);

/// The configuration of the OPW model at angles theta.
ArmConfiguration opw_configuration(const OpwParameters& p, const ModelAngles& theta);

/// The configuration of the UR model at angles theta.
ArmConfiguration ur_configuration(const UrParameters& p, const ModelAngles& theta);

}  // namespace grpvss::kinematics
