#pragma once
// Values of the movable joints off the chain: the caller's, a mimic rule's, or 0 clamped into
// the limits; with a bound on the mimic arithmetic (proof: proofs/urdf-frames.md#mimic-value).
// Private to src/io.

#include <map>
#include <set>
#include <string>

#include <urdf_model/joint.h>

#include "grpvss/model/robot_description.hpp"
#include "urdf_tree.hpp"
#include "urdf_xml.hpp"

namespace grpvss::io {

struct JointValue {
  double value = 0.0;
  double error = 0.0;  ///< bound on |value - exact value|
};

/// \brief Resolves every side joint's value. `chain_joints` are the names of the chain's
/// movable joints. \throws InputError for an unknown or chain joint named in
/// `requested`, a value outside the limits, a mimic of an unknown or chain joint, a mimic
/// cycle, or a value requested for a mimic joint.
std::map<std::string, JointValue> resolve_side_joint_values(
    const UrdfXml& xml, const UrdfTree& tree, const std::set<std::string>& chain_joints,
    const std::map<std::string, double>& requested);

/// Limits of a movable joint as GRPVSS uses them: [lower, upper] (continuous: [-inf, +inf]).
/// \throws InputError when lower > upper or a limit is not an accepted number.
std::pair<double, double> joint_limits(const UrdfXml& xml, const urdf::Joint& joint);

}  // namespace grpvss::io
