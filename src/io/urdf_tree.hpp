#pragma once
// The link tree of a URDF: parent joint of each link, children in document order, a check that
// it really is one tree. Private to src/io.

#include <map>
#include <string>
#include <vector>

#include <urdf_model/model.h>

#include "urdf_xml.hpp"

namespace grpvss::io {

/// \brief Checks on the XML, before urdfdom builds its (shared-pointer) tree: no link is the
/// child of two joints and the joints form no cycle. \throws InputError naming the joints.
void check_joint_graph(const UrdfXml& xml);

class UrdfTree {
 public:
  /// \throws InputError when a link is the child of two joints or not connected to the root.
  UrdfTree(const urdf::ModelInterface& model, const UrdfXml& xml);

  const std::string& root() const { return root_; }
  bool has_link(const std::string& link) const { return children_.count(link) > 0; }
  /// The joint whose child is `link`; nullptr for the root.
  const urdf::Joint* parent_joint(const std::string& link) const;
  /// Joints whose parent is `link`, in document order.
  const std::vector<const urdf::Joint*>& child_joints(const std::string& link) const;
  /// Every link, depth first from the root, children in document order.
  const std::vector<std::string>& links_in_tree_order() const { return order_; }
  /// The joints from the root down to `link`.
  std::vector<const urdf::Joint*> joints_from_root(const std::string& link) const;

 private:
  void visit(const std::string& link, int depth);

  std::string root_;
  std::map<std::string, const urdf::Joint*> parent_;
  std::map<std::string, std::vector<const urdf::Joint*>> children_;
  std::vector<std::string> order_;
};

/// True for revolute, continuous and prismatic joints.
bool is_movable(const urdf::Joint& joint);

}  // namespace grpvss::io
