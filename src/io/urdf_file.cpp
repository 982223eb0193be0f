#include "grpvss/io/urdf_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>
#include <stdexcept>
#include <tuple>

#include <Eigen/Geometry>
#include <urdf_model/link.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/mesh_file.hpp"
#include "grpvss/io/resource_path.hpp"
#include "grpvss/io/text_file.hpp"
#include "round_trip_text.hpp"
#include "urdf_joint_values.hpp"
#include "urdf_tree.hpp"
#include "urdf_xml.hpp"
#include "urdfdom_parse.hpp"

namespace grpvss::io {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string text_of(const Eigen::Vector3d& v) {
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%.17g %.17g %.17g", v.x(), v.y(), v.z());
  return buffer;
}

Eigen::Vector3d to_eigen(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }

bool accepted(const Eigen::Vector3d& v) {
  return is_accepted_magnitude(v.x()) && is_accepted_magnitude(v.y()) &&
         is_accepted_magnitude(v.z());
}

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "'" : ", '") + name + "'";
  return text;
}

// "1", "+1", "1.", "1.000", "01": a decimal that is exactly 1.
bool is_exactly_one(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  while (token.size() > 1 && token.front() == '0' && token[1] != '.') token.remove_prefix(1);
  if (token.empty() || token.front() != '1') return false;
  token.remove_prefix(1);
  if (token.empty()) return true;
  if (token.front() != '.') return false;
  token.remove_prefix(1);
  return std::all_of(token.begin(), token.end(), [](char c) { return c == '0'; });
}

// The `scale` attribute holds exact numbers when absent or when every component is 1.
bool mesh_scale_is_exact(const tinyxml2::XMLElement* mesh) {
  const char* scale = mesh != nullptr ? mesh->Attribute("scale") : nullptr;
  if (scale == nullptr) return true;
  std::string_view rest(scale);
  int count = 0;
  while (true) {
    const std::size_t begin = rest.find_first_not_of(" \t\r\n");
    if (begin == std::string_view::npos) break;
    rest.remove_prefix(begin);
    const std::size_t end = std::min(rest.find_first_of(" \t\r\n"), rest.size());
    if (!is_exactly_one(rest.substr(0, end))) return false;
    rest.remove_prefix(end);
    ++count;
  }
  return count == 3;
}

using MeshKey = std::tuple<std::string, double, double, double, bool>;

class DescriptionBuilder {
 public:
  DescriptionBuilder(const urdf::ModelInterface& model, const UrdfXml& xml, const UrdfTree& tree,
                     const UrdfReadOptions& options, std::vector<InputWarning>& warnings)
      : model_(model), xml_(xml), tree_(tree), options_(options), warnings_(warnings) {
    package_directories_ = options.package_paths;
    if (options.use_ros_package_path) {
      for (std::string& d : ros_package_path_directories()) package_directories_.push_back(d);
    }
    base_directory_ = std::filesystem::path(xml.file()).parent_path().string();
  }

  RobotDescription build() {
    RobotDescription description;
    description.name = model_.getName();
    description.source = xml_.file();
    description.root_link = tree_.root();
    description.tip_link = choose_tip();
    find_chain(description.tip_link);
    assign_components();
    check_option_names();
    side_values_ = resolve_side_joint_values(xml_, tree_, chain_names_, options_.side_joint_values);
    for (std::size_t i = 0; i < chain_.size(); ++i) {
      description.joints.push_back(describe_chain_joint(i));
    }
    for (int i = 0; i <= static_cast<int>(chain_.size()); ++i) {
      description.links.push_back(describe_link(i));
    }
    description.last_child_to_tip = path_between(chain_.back()->child_link_name, tip_);
    description.side_joints = describe_side_joints();
    return description;
  }

 private:
  int joint_line(const std::string& name) const { return UrdfXml::line(xml_.joint(name)); }

  std::string choose_tip() {
    if (!options_.tip.empty()) {
      if (!tree_.has_link(options_.tip)) {
        throw InputError(xml_.file(), 0, "a tip that is a link of the URDF",
                         "no link '" + options_.tip + "'");
      }
      return tip_ = options_.tip;
    }
    std::vector<std::string> leaves;
    for (const std::string& link : tree_.links_in_tree_order()) {
      const auto joints = tree_.joints_from_root(link);
      const bool moved = std::any_of(joints.begin(), joints.end(),
                                     [](const urdf::Joint* j) { return is_movable(*j); });
      if (tree_.child_joints(link).empty() && moved) leaves.push_back(link);
    }
    if (leaves.empty()) {
      throw InputError(xml_.file(), 0, "a leaf link reached from the root through a movable joint",
                       "none");
    }
    if (leaves.size() > 1) {
      throw InputError(xml_.file(), 0, "one leaf link reached through movable joints, or a named tip",
                       "leaves " + join(leaves));
    }
    return tip_ = leaves.front();
  }

  void find_chain(const std::string& tip) {
    for (const urdf::Joint* joint : tree_.joints_from_root(tip)) {
      if (joint->type != urdf::Joint::FIXED && !is_movable(*joint)) {
        throw InputError(xml_.file(), joint_line(joint->name),
                         "revolute, continuous, prismatic or fixed joints on the chain from '" +
                             tree_.root() + "' to '" + tip + "'",
                         "joint '" + joint->name + "' of type " + type_name(*joint));
      }
      if (!is_movable(*joint)) continue;
      if (joint->mimic != nullptr) {
        throw InputError(xml_.file(), joint_line(joint->name),
                         "chain joints without <mimic> (a mimic joint on the chain is not "
                         "supported: choose a tip before it)",
                         "joint '" + joint->name + "' mimics '" + joint->mimic->joint_name + "'");
      }
      chain_index_[joint->name] = static_cast<int>(chain_.size());
      chain_.push_back(joint);
      chain_names_.insert(joint->name);
    }
    if (chain_.empty()) {
      throw InputError(xml_.file(), 0,
                       "a movable joint between the root '" + tree_.root() + "' and the tip '" +
                           tip + "'",
                       "none");
    }
  }

  static std::string type_name(const urdf::Joint& joint) {
    switch (joint.type) {
      case urdf::Joint::FLOATING: return "floating";
      case urdf::Joint::PLANAR: return "planar";
      case urdf::Joint::REVOLUTE: return "revolute";
      case urdf::Joint::CONTINUOUS: return "continuous";
      case urdf::Joint::PRISMATIC: return "prismatic";
      case urdf::Joint::FIXED: return "fixed";
      default: return "unknown";
    }
  }

  // Chain link of every URDF link: that of its parent, one more past a chain joint.
  void assign_components() {
    for (const std::string& link : tree_.links_in_tree_order()) {
      const urdf::Joint* joint = tree_.parent_joint(link);
      if (joint == nullptr) {
        component_[link] = 0;
      } else if (const auto it = chain_index_.find(joint->name); it != chain_index_.end()) {
        component_[link] = it->second + 1;
      } else {
        component_[link] = component_.at(joint->parent_link_name);
      }
    }
  }

  void check_option_names() const {
    if (!(options_.default_acceleration > 0) || !std::isfinite(options_.default_acceleration)) {
      throw InputError(xml_.file(), 0, "a positive, finite default acceleration",
                       round_trip_text(options_.default_acceleration));
    }
    for (const auto& [name, value] : options_.accelerations) {
      if (chain_names_.count(name) == 0) {
        throw InputError(xml_.file(), joint_line(name), "a chain joint to set an acceleration for",
                         "joint '" + name + "'" + (xml_.joint(name) ? ", not on the chain" : ", not in the URDF"));
      }
      if (!(value > 0) || !std::isfinite(value)) {
        throw InputError(xml_.file(), joint_line(name),
                         "a positive, finite acceleration for joint '" + name + "'", round_trip_text(value));
      }
    }
  }

  std::string frame_of(int chain_link) const {
    if (chain_link == static_cast<int>(chain_.size())) return tip_;
    return chain_link == 0 ? tree_.root() : chain_[static_cast<std::size_t>(chain_link) - 1]->child_link_name;
  }

  UrdfOrigin origin_of(const urdf::Pose& pose, const tinyxml2::XMLElement* element,
                       const std::string& owner) const {
    if (element == nullptr) {
      throw InputError(xml_.file(), 0, "the XML element of " + owner, "none (a parser disagreement)");
    }
    UrdfOrigin origin;
    origin.xyz = to_eigen(pose.position);
    origin.rpy = xml_.origin_rpy(*element, owner);
    const tinyxml2::XMLElement* origin_element = element->FirstChildElement("origin");
    if (!accepted(origin.xyz)) {
      throw InputError(xml_.file(), UrdfXml::line(origin_element),
                       "<origin xyz> of " + owner + ", each 0 or of magnitude within [1e-300, 1e9]",
                       text_of(origin.xyz));
    }
    check_rotation_agrees(pose.rotation, origin.rpy, origin_element, owner);
    return origin;
  }

  // urdfdom keeps only a quaternion made from rpy; GRPVSS reads rpy itself. The two readings
  // must agree (they differ only if the two XML parsers saw different text).
  void check_rotation_agrees(const urdf::Rotation& q, const Eigen::Vector3d& rpy,
                             const tinyxml2::XMLElement* origin, const std::string& owner) const {
    const Eigen::Matrix3d ours = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                                  Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                                  Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix();
    const Eigen::Matrix3d theirs = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
    if (!((ours - theirs).cwiseAbs().maxCoeff() <= 1e-6)) {
      throw InputError(xml_.file(), UrdfXml::line(origin),
                       "an <origin rpy> of " + owner + " that urdfdom and GRPVSS read alike",
                       "a different rotation");
    }
  }

  UrdfOrigin joint_origin(const urdf::Joint& joint) const {
    return origin_of(joint.parent_to_joint_origin_transform, xml_.joint(joint.name),
                     "joint '" + joint.name + "'");
  }

  Eigen::Vector3d joint_axis(const urdf::Joint& joint) const {
    const Eigen::Vector3d axis = to_eigen(joint.axis);
    if (!accepted(axis) || axis == Eigen::Vector3d::Zero()) {
      throw InputError(xml_.file(), joint_line(joint.name),
                       "a nonzero <axis xyz> for joint '" + joint.name +
                           "', each component 0 or of magnitude within [1e-300, 1e9]",
                       text_of(axis));
    }
    return axis;
  }

  FrameStep motion_step(const urdf::Joint& joint, double sign) const {
    FrameStep step;
    step.kind = joint.type == urdf::Joint::PRISMATIC ? FrameStep::Kind::kTranslation
                                                     : FrameStep::Kind::kRotation;
    step.axis = joint_axis(joint);
    const JointValue& value = side_values_.at(joint.name);
    step.value = sign * value.value;
    step.value_error = value.error;
    step.joint = joint.name;
    return step;
  }

  void check_side_step(const urdf::Joint& joint) const {
    if (chain_names_.count(joint.name) > 0) {
      throw std::logic_error("urdf: a path inside one chain link crossed chain joint " + joint.name);
    }
    if (joint.type != urdf::Joint::FIXED && !is_movable(joint)) {
      throw InputError(xml_.file(), joint_line(joint.name),
                       "revolute, continuous, prismatic or fixed joints in side branches",
                       "joint '" + joint.name + "' of type " + type_name(joint));
    }
  }

  // Parent to child through `joint`: its origin, then its motion at the side value.
  void append_down(const urdf::Joint& joint, FramePath& path) const {
    check_side_step(joint);
    FrameStep origin;
    origin.kind = FrameStep::Kind::kOrigin;
    origin.origin = joint_origin(joint);
    origin.joint = joint.name;
    path.push_back(origin);
    if (is_movable(joint)) path.push_back(motion_step(joint, 1.0));
  }

  // Child to parent: the inverse motion, then the inverse origin.
  void append_up(const urdf::Joint& joint, FramePath& path) const {
    check_side_step(joint);
    if (is_movable(joint)) path.push_back(motion_step(joint, -1.0));
    FrameStep origin;
    origin.kind = FrameStep::Kind::kInverseOrigin;
    origin.origin = joint_origin(joint);
    origin.joint = joint.name;
    path.push_back(origin);
  }

  // From link `from` to link `to` (one chain link): up to their common ancestor, then down.
  FramePath path_between(const std::string& from, const std::string& to) const {
    std::set<std::string> above_from;
    for (std::string link = from;; link = tree_.parent_joint(link)->parent_link_name) {
      above_from.insert(link);
      if (tree_.parent_joint(link) == nullptr) break;
    }
    std::vector<const urdf::Joint*> down;
    std::string common = to;
    while (above_from.count(common) == 0) {
      const urdf::Joint* joint = tree_.parent_joint(common);
      down.push_back(joint);
      common = joint->parent_link_name;
    }
    FramePath path;
    for (std::string link = from; link != common; link = tree_.parent_joint(link)->parent_link_name) {
      append_up(*tree_.parent_joint(link), path);
    }
    for (auto it = down.rbegin(); it != down.rend(); ++it) append_down(**it, path);
    return path;
  }

  ChainJointDescription describe_chain_joint(std::size_t i) const {
    const urdf::Joint& joint = *chain_[i];
    ChainJointDescription d;
    d.name = joint.name;
    d.type = joint.type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
    d.continuous = joint.type == urdf::Joint::CONTINUOUS;
    d.parent_link = joint.parent_link_name;
    d.child_link = joint.child_link_name;
    d.line = joint_line(joint.name);
    d.parent_to_joint = path_between(frame_of(static_cast<int>(i)), joint.parent_link_name);
    FrameStep origin;
    origin.origin = joint_origin(joint);
    origin.joint = joint.name;
    d.parent_to_joint.push_back(origin);
    d.axis = joint_axis(joint);
    std::tie(d.minimum, d.maximum) = joint_limits(xml_, joint);
    d.velocity = joint_velocity(joint);
    const auto it = options_.accelerations.find(joint.name);
    d.acceleration = it != options_.accelerations.end() ? it->second : options_.default_acceleration;
    d.home = std::clamp(0.0, d.minimum, d.maximum);
    if (!d.continuous && d.minimum == d.maximum) {
      warnings_.push_back({xml_.file(), d.line, "joint '" + d.name + "' has equal lower and upper "
                           "limits: it cannot move"});
    }
    return d;
  }

  double joint_velocity(const urdf::Joint& joint) const {
    if (joint.limits == nullptr) return kInfinity;
    const double velocity = joint.limits->velocity;
    if (!is_accepted_magnitude(velocity) || velocity < 0) {
      throw InputError(xml_.file(), joint_line(joint.name),
                       "a velocity limit >= 0 for joint '" + joint.name + "'", round_trip_text(velocity));
    }
    return velocity;
  }

  ChainLinkDescription describe_link(int i) {
    ChainLinkDescription d;
    d.frame = frame_of(i);
    for (const std::string& name : tree_.links_in_tree_order()) {
      if (component_.at(name) != i) continue;
      d.urdf_links.push_back(name);
      d.frame_paths.push_back(path_between(d.frame, name));
      const urdf::LinkConstSharedPtr link = model_.getLink(name);
      for (std::size_t k = 0; k < link->collision_array.size(); ++k) {
        d.collisions.push_back(describe_collision(*link, static_cast<int>(k), d.frame));
      }
    }
    return d;
  }

  CollisionDescription describe_collision(const urdf::Link& link, int index, const std::string& frame) {
    const urdf::Collision& collision = *link.collision_array[static_cast<std::size_t>(index)];
    const tinyxml2::XMLElement* element = xml_.collision(link.name, index);
    CollisionDescription d;
    d.link = link.name;
    d.name = collision.name;
    d.index = index;
    d.line = UrdfXml::line(element);
    const std::string owner = "<collision> " + std::to_string(index) + " of link '" + link.name + "'";
    d.link_to_collision = path_between(frame, link.name);
    FrameStep origin;
    origin.origin = origin_of(collision.origin, element, owner);
    d.link_to_collision.push_back(origin);
    if (collision.geometry == nullptr) {
      throw InputError(xml_.file(), d.line, "a <geometry> in " + owner, "none");
    }
    describe_geometry(*collision.geometry, element, owner, d);
    return d;
  }

  void require_positive(double x, const std::string& what, const std::string& owner, int line) const {
    if (!(x > 0) || !is_accepted_magnitude(x)) {
      throw InputError(xml_.file(), line, "a positive " + what + " in " + owner + " (at most 1e9)",
                       round_trip_text(x));
    }
  }

  void describe_geometry(const urdf::Geometry& geometry, const tinyxml2::XMLElement* element,
                         const std::string& owner, CollisionDescription& d) {
    switch (geometry.type) {
      case urdf::Geometry::BOX: {
        d.shape = CollisionShape::kBox;
        d.box_size = to_eigen(static_cast<const urdf::Box&>(geometry).dim);
        for (int i = 0; i < 3; ++i) require_positive(d.box_size[i], "box size", owner, d.line);
        return;
      }
      case urdf::Geometry::CYLINDER: {
        const auto& cylinder = static_cast<const urdf::Cylinder&>(geometry);
        d.shape = CollisionShape::kCylinder;
        d.radius = cylinder.radius;
        d.length = cylinder.length;
        require_positive(d.radius, "cylinder radius", owner, d.line);
        require_positive(d.length, "cylinder length", owner, d.line);
        return;
      }
      case urdf::Geometry::SPHERE: {
        d.shape = CollisionShape::kSphere;
        d.radius = static_cast<const urdf::Sphere&>(geometry).radius;
        require_positive(d.radius, "sphere radius", owner, d.line);
        return;
      }
      case urdf::Geometry::MESH: {
        const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
        d.shape = CollisionShape::kMesh;
        d.mesh_uri = mesh.filename;
        d.mesh_scale = to_eigen(mesh.scale);
        for (int i = 0; i < 3; ++i) {
          if (d.mesh_scale[i] == 0.0 || !is_accepted_magnitude(d.mesh_scale[i])) {
            throw InputError(xml_.file(), d.line, "a nonzero <mesh scale> in " + owner +
                             ", of magnitude within [1e-300, 1e9]", text_of(d.mesh_scale));
          }
        }
        if (options_.load_meshes) load_mesh(d, mesh_element(element), owner);
        return;
      }
    }
    throw InputError(xml_.file(), d.line, "a box, cylinder, sphere or mesh in " + owner, "another shape");
  }

  static const tinyxml2::XMLElement* mesh_element(const tinyxml2::XMLElement* collision) {
    const tinyxml2::XMLElement* geometry =
        collision != nullptr ? collision->FirstChildElement("geometry") : nullptr;
    return geometry != nullptr ? geometry->FirstChildElement() : nullptr;
  }

  void load_mesh(CollisionDescription& d, const tinyxml2::XMLElement* element, const std::string& owner) {
    const ResolvedResource resolved = resolve_resource(d.mesh_uri, base_directory_, package_directories_);
    if (resolved.path.empty()) {
      std::string found = resolved.tried.empty() ? std::string("nothing to try")
                                                 : "no file among " + join(resolved.tried);
      if (d.mesh_uri.rfind("package://", 0) == 0 && package_directories_.empty()) {
        found = "no package directories (--package-path, package_paths, ROS_PACKAGE_PATH)";
      }
      throw InputError(xml_.file(), d.line, "mesh '" + d.mesh_uri + "' of " + owner + " to resolve to a file", found);
    }
    d.mesh_file = resolved.path;
    MeshReadOptions mesh_options;
    mesh_options.scale = d.mesh_scale;
    mesh_options.scale_is_exact = mesh_scale_is_exact(element);
    mesh_options.apply_collada_up_axis = options_.apply_collada_up_axis;
    const MeshKey key{d.mesh_file, d.mesh_scale.x(), d.mesh_scale.y(), d.mesh_scale.z(),
                      mesh_options.scale_is_exact};
    auto it = meshes_.find(key);
    if (it == meshes_.end()) {
      try {
        it = meshes_.emplace(key, read_mesh_file(d.mesh_file, mesh_options)).first;
      } catch (const InputError& error) {
        throw InputError(xml_.file(), d.line, "a readable mesh for " + owner, error.what());
      }
    }
    d.mesh = it->second.mesh;
    d.mesh_vertex_error = it->second.vertex_error;
  }

  std::vector<SideJointDescription> describe_side_joints() const {
    std::vector<SideJointDescription> sides;
    for (const std::string& link : tree_.links_in_tree_order()) {
      const urdf::Joint* joint = tree_.parent_joint(link);
      if (joint == nullptr || !is_movable(*joint) || chain_names_.count(joint->name) > 0) continue;
      SideJointDescription d;
      d.name = joint->name;
      d.type = joint->type == urdf::Joint::PRISMATIC ? JointType::kPrismatic : JointType::kRevolute;
      d.continuous = joint->type == urdf::Joint::CONTINUOUS;
      d.value = side_values_.at(joint->name).value;
      d.value_error = side_values_.at(joint->name).error;
      std::tie(d.minimum, d.maximum) = joint_limits(xml_, *joint);
      if (joint->mimic != nullptr) {
        d.mimics = joint->mimic->joint_name;
        d.multiplier = joint->mimic->multiplier;
        d.offset = joint->mimic->offset;
      }
      d.carried_by = component_.at(link);
      d.line = joint_line(joint->name);
      sides.push_back(d);
    }
    return sides;
  }

  const urdf::ModelInterface& model_;
  const UrdfXml& xml_;
  const UrdfTree& tree_;
  const UrdfReadOptions& options_;
  std::vector<InputWarning>& warnings_;
  std::vector<std::string> package_directories_;
  std::string base_directory_;
  std::string tip_;
  std::vector<const urdf::Joint*> chain_;
  std::set<std::string> chain_names_;
  std::map<std::string, int> chain_index_;
  std::map<std::string, int> component_;
  std::map<std::string, JointValue> side_values_;
  std::map<MeshKey, MeshFile> meshes_;
};

}  // namespace

UrdfReadResult parse_urdf(std::string_view text, const std::string& file_name,
                          const UrdfReadOptions& options) {
  const UrdfXml xml(text, file_name);
  check_joint_graph(xml);
  UrdfdomModel parsed = parse_with_urdfdom(text, file_name);
  const UrdfTree tree(*parsed.model, xml);
  UrdfReadResult result;
  result.warnings = std::move(parsed.warnings);
  result.description = DescriptionBuilder(*parsed.model, xml, tree, options, result.warnings).build();
  return result;
}

UrdfReadResult read_urdf_file(const std::string& path, const UrdfReadOptions& options) {
  return parse_urdf(read_text_file(path), path, options);
}

}  // namespace grpvss::io
