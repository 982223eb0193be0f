#pragma once
// The KRL system variables the reader follows ($TOOL, $BASE, $VEL, $ACC, $VEL_AXIS,
// $ACC_AXIS, $APO, $IPO_MODE), in KRL units until a motion takes a snapshot in SI.

#include <array>
#include <optional>
#include <string>

#include "grpvss/model/robot_program.hpp"
#include "krl_data.hpp"
#include "krl_value.hpp"
#include "program_recorder.hpp"

namespace grpvss::io::krl {

struct MotionState {
  std::optional<Value> tool;  ///< FRAME structure (mm, degrees)
  std::string tool_name;
  std::optional<Value> base;
  std::string base_name;
  std::optional<double> vel_cp, vel_ori1, vel_ori2;  ///< m/s, deg/s, deg/s
  std::optional<double> acc_cp, acc_ori1;            ///< m/s^2, deg/s^2
  std::array<std::optional<double>, 6> vel_axis{}, acc_axis{};  ///< percent
  std::optional<double> apo_cdis, apo_cptp, apo_cori, apo_cvel;  ///< mm, %, deg, %

  /// BAS(#INITMOV): every speed, acceleration and approximation parameter back to the
  /// controller's default (unset); $TOOL and $BASE stay.
  void reset_motion_parameters();
  /// The speeds in effect, in SI.
  MotionSpeed speed() const;
  /// $TOOL, $BASE, $VEL, $ACC, $APO, $VEL_AXIS[i], $ACC_AXIS[i] as KRL values; std::nullopt
  /// for other keys.
  std::optional<Value> system_value(const std::string& key) const;
};

/// \brief Applies `target = value` when target is a system variable the reader follows.
/// Returns false for every other system variable (the caller warns). `value_text` names the
/// value ($TOOL = TOOL_DATA[1] gives the tool the name "TOOL_DATA[1]").
/// \throws InputError for an unknown $TOOL/$BASE, a value of the wrong type or range, and
/// $IPO_MODE = #TCP (an external TCP is not read).
bool assign_system_variable(MotionState& state, const Designator& target, const Value& value,
                            const std::string& value_text, const TokenCursor& cursor,
                            ProgramRecorder& recorder);

}  // namespace grpvss::io::krl
