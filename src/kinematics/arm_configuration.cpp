#include "grpvss/kinematics/arm_configuration.hpp"

#include <cmath>

namespace grpvss::kinematics {
namespace {

const char* shoulder_name(Shoulder s) {
  switch (s) {
    case Shoulder::kFront: return "front";
    case Shoulder::kBack: return "back";
    case Shoulder::kLeft: return "left";
    case Shoulder::kRight: return "right";
  }
  return "?";
}

const char* wrist_name(Wrist w) {
  switch (w) {
    case Wrist::kNoFlip: return "no flip";
    case Wrist::kFlip: return "flip";
    case Wrist::kUp: return "wrist up";
    case Wrist::kDown: return "wrist down";
  }
  return "?";
}

// Elbow above the chord, seen with the reach pointing away from axis 1: the chord-side sign
// (in front of the lower arm / the 2-D cross product chord x elbow) agrees with the reach side.
Elbow elbow_from(double reach_side, double chord_side) {
  return (reach_side >= 0) == (chord_side >= 0) ? Elbow::kUp : Elbow::kDown;
}

}  // namespace

bool operator==(const ArmConfiguration& a, const ArmConfiguration& b) {
  return a.shoulder == b.shoulder && a.elbow == b.elbow && a.wrist == b.wrist;
}

bool operator!=(const ArmConfiguration& a, const ArmConfiguration& b) { return !(a == b); }

std::string to_string(const ArmConfiguration& c) {
  return std::string(shoulder_name(c.shoulder)) + ", elbow " +
         (c.elbow == Elbow::kUp ? "up" : "down") + ", " + wrist_name(c.wrist);
}

std::ostream& operator<<(std::ostream& out, const ArmConfiguration& c) { return out << to_string(c); }

ArmConfiguration opw_configuration(const OpwParameters& p, const ModelAngles& theta) {
  const OpwArmSides sides = opw_arm_sides(p, theta);
  ArmConfiguration c;
  c.shoulder = sides.wrist_ahead_of_axis1 >= 0 ? Shoulder::kFront : Shoulder::kBack;
  c.elbow = elbow_from(sides.wrist_ahead_of_axis1, sides.wrist_ahead_of_lower_arm);
  c.wrist = std::sin(theta[4]) < 0 ? Wrist::kFlip : Wrist::kNoFlip;
  return c;
}

ArmConfiguration ur_configuration(const UrParameters& p, const ModelAngles& theta) {
  const UrArmSides sides = ur_arm_sides(p, theta);
  ArmConfiguration c;
  // The arm plane is d4 along z1 = x1 turned clockwise (seen from above): to the right of a
  // reach along +x1 when d4 > 0.
  const double right = (p.d4 < 0 ? -1.0 : 1.0) * sides.wrist_ahead_of_axis1;
  c.shoulder = right > 0 ? Shoulder::kRight : Shoulder::kLeft;
  c.elbow = elbow_from(sides.wrist_ahead_of_axis1, sides.elbow_over_chord);
  c.wrist = std::sin(theta[4]) < 0 ? Wrist::kDown : Wrist::kUp;
  return c;
}

}  // namespace grpvss::kinematics
