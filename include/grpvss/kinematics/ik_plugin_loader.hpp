#pragma once
/// \file
/// \brief Loads a user IK routine (the thesis's INVERS) from a shared library at run time.
/// The C ABI the library implements is grpvss/kinematics/ik_plugin.h (docs/ik-plugin.md).

#include <memory>
#include <string>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

/// \brief dlopen()s the library and resolves grpvss_ik_abi_version and grpvss_ik_solve
/// (grpvss_ik_name optional). Throws grpvss::InputError naming the file when it cannot be
/// loaded, a symbol is missing or the ABI version differs from GRPVSS_IK_ABI_VERSION.
/// solve() throws InputError when the plug-in returns a code other than 0 or 1.
std::unique_ptr<InverseKinematics> load_ik_plugin(const std::string& shared_library_path,
                                                  const RobotModel& model);

}  // namespace grpvss::kinematics
