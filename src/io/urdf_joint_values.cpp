#include "urdf_joint_values.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "grpvss/common/input_error.hpp"
#include "grpvss/common/unit_roundoff.hpp"
#include "round_trip_text.hpp"

namespace grpvss::io {
namespace {

class SideJointResolver {
 public:
  SideJointResolver(const UrdfXml& xml, const UrdfTree& tree, const std::set<std::string>& chain,
                    const std::map<std::string, double>& requested)
      : xml_(xml), chain_(chain), requested_(requested) {
    for (const std::string& link : tree.links_in_tree_order()) {
      const urdf::Joint* joint = tree.parent_joint(link);
      if (joint != nullptr && is_movable(*joint) && chain.count(joint->name) == 0) {
        side_[joint->name] = joint;
      }
    }
  }

  std::map<std::string, JointValue> resolve() {
    check_requested_names();
    for (const auto& [name, joint] : side_) value_of(*joint, 0);
    return values_;
  }

 private:
  int line(const std::string& joint) const { return UrdfXml::line(xml_.joint(joint)); }

  void check_requested_names() const {
    for (const auto& [name, value] : requested_) {
      if (chain_.count(name) > 0) {
        throw InputError(xml_.file(), line(name), "a side-branch joint to set a value for",
                         "joint '" + name + "', which is on the chain");
      }
      if (side_.count(name) == 0) {
        throw InputError(xml_.file(), 0, "a movable side-branch joint to set a value for",
                         "no such joint '" + name + "'");
      }
    }
  }

  JointValue value_of(const urdf::Joint& joint, int depth) {
    if (const auto it = values_.find(joint.name); it != values_.end()) return it->second;
    if (depth > static_cast<int>(side_.size())) {
      throw InputError(xml_.file(), line(joint.name), "mimic joints without a cycle",
                       "a cycle through joint '" + joint.name + "'");
    }
    const auto [lower, upper] = joint_limits(xml_, joint);
    JointValue value;
    if (joint.mimic != nullptr) {
      value = mimic_value(joint, depth);
    } else if (const auto it = requested_.find(joint.name); it != requested_.end()) {
      value.value = it->second;
    } else {
      value.value = std::clamp(0.0, lower, upper);
    }
    // Values are 0 or of magnitude >= 1e-300 like every number of the description, so the
    // arithmetic on them stays clear of underflow (proofs/urdf-frames.md#setting).
    if (!is_accepted_magnitude(value.value) || value.value < lower || value.value > upper) {
      throw InputError(xml_.file(), line(joint.name),
                       "a value within [" + round_trip_text(lower) + ", " + round_trip_text(upper) +
                           "] for joint '" + joint.name + "'",
                       round_trip_text(value.value));
    }
    values_[joint.name] = value;
    return value;
  }

  // value = multiplier * master + offset; the bound is
  // 2 (gamma_3 (|m| |v_M| + |o|) + (1 + gamma_1) |m| e_M) + 2^-1073 (an underflowing product).
  // proof: proofs/urdf-frames.md#mimic-value
  JointValue mimic_value(const urdf::Joint& joint, int depth) {
    const std::string& master = joint.mimic->joint_name;
    if (requested_.count(joint.name) > 0) {
      throw InputError(xml_.file(), line(joint.name), "a value for the master joint '" + master +
                           "' rather than for its mimic",
                       "a value for joint '" + joint.name + "'");
    }
    if (chain_.count(master) > 0) {
      throw InputError(xml_.file(), line(joint.name),
                       "side-branch joints that mimic side-branch joints (a mimic of a chain "
                       "joint is not supported)",
                       "joint '" + joint.name + "' mimics chain joint '" + master + "'");
    }
    const auto it = side_.find(master);
    if (it == side_.end()) {
      throw InputError(xml_.file(), line(joint.name), "a movable master joint for <mimic>",
                       "joint '" + joint.name + "' mimics '" + master + "'");
    }
    const JointValue master_value = value_of(*it->second, depth + 1);
    const tinyxml2::XMLElement* element = xml_.joint(joint.name);
    const tinyxml2::XMLElement* mimic = element ? element->FirstChildElement("mimic") : nullptr;
    const std::string owner = "<mimic> of joint '" + joint.name + "'";
    const double m = mimic ? xml_.number_attribute(*mimic, "multiplier", 1.0, owner) : 1.0;
    const double o = mimic ? xml_.number_attribute(*mimic, "offset", 0.0, owner) : 0.0;
    JointValue value;
    value.value = m * master_value.value + o;
    value.error = 2 * (gamma(3) * (std::abs(m) * std::abs(master_value.value) + std::abs(o)) +
                       (1 + gamma(1)) * std::abs(m) * master_value.error) +
                  std::ldexp(1.0, -1073);
    return value;
  }

  const UrdfXml& xml_;
  const std::set<std::string>& chain_;
  const std::map<std::string, double>& requested_;
  std::map<std::string, const urdf::Joint*> side_;
  std::map<std::string, JointValue> values_;
};

}  // namespace

std::pair<double, double> joint_limits(const UrdfXml& xml, const urdf::Joint& joint) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  if (joint.type == urdf::Joint::CONTINUOUS) return {-kInfinity, kInfinity};
  const int line = UrdfXml::line(xml.joint(joint.name));
  if (joint.limits == nullptr) {
    throw InputError(xml.file(), line, "a <limit> for joint '" + joint.name + "'", "none");
  }
  const double lower = joint.limits->lower;
  const double upper = joint.limits->upper;
  if (!is_accepted_magnitude(lower) || !is_accepted_magnitude(upper) || lower > upper) {
    throw InputError(xml.file(), line,
                     "limits lower <= upper for joint '" + joint.name +
                         "', each 0 or of magnitude within [1e-300, 1e9]",
                     "lower " + round_trip_text(lower) + ", upper " + round_trip_text(upper));
  }
  return {lower, upper};
}

std::map<std::string, JointValue> resolve_side_joint_values(
    const UrdfXml& xml, const UrdfTree& tree, const std::set<std::string>& chain_joints,
    const std::map<std::string, double>& requested) {
  return SideJointResolver(xml, tree, chain_joints, requested).resolve();
}

}  // namespace grpvss::io
