#include "urdf_tree.hpp"

#include <algorithm>
#include <set>

#include "grpvss/common/input_error.hpp"

namespace grpvss::io {
namespace {

std::string link_attribute(const tinyxml2::XMLElement& joint, const char* child) {
  const tinyxml2::XMLElement* element = joint.FirstChildElement(child);
  const char* link = element != nullptr ? element->Attribute("link") : nullptr;
  return link != nullptr ? link : "";
}

std::string joint_name(const tinyxml2::XMLElement& joint) {
  const char* name = joint.Attribute("name");
  return name != nullptr ? name : "";
}

}  // namespace

void check_joint_graph(const UrdfXml& xml) {
  // child link -> (joint element, parent link)
  std::map<std::string, std::pair<const tinyxml2::XMLElement*, std::string>> parent_of;
  for (const tinyxml2::XMLElement* joint = xml.first_joint(); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    const std::string child = link_attribute(*joint, "child");
    const std::string parent = link_attribute(*joint, "parent");
    if (child.empty() || parent.empty()) continue;  // urdfdom reports it
    const auto [it, inserted] = parent_of.emplace(child, std::make_pair(joint, parent));
    if (!inserted) {
      throw InputError(xml.file(), UrdfXml::line(joint),
                       "each link to be the child of at most one joint",
                       "link '" + child + "' is the child of joint '" +
                           joint_name(*it->second.first) + "' and of joint '" +
                           joint_name(*joint) + "'");
    }
  }
  for (const auto& [start, entry] : parent_of) {
    std::set<std::string> seen{start};
    std::string link = entry.second;
    for (auto it = parent_of.find(link); it != parent_of.end(); it = parent_of.find(link)) {
      if (!seen.insert(link).second) {
        throw InputError(xml.file(), UrdfXml::line(it->second.first), "joints that form a tree",
                         "a cycle of joints through link '" + link + "'");
      }
      link = it->second.second;
    }
  }
}

UrdfTree::UrdfTree(const urdf::ModelInterface& model, const UrdfXml& xml) {
  for (const auto& [name, link] : model.links_) children_[name];
  std::vector<const urdf::Joint*> joints;
  for (const auto& [name, joint] : model.joints_) joints.push_back(joint.get());
  std::sort(joints.begin(), joints.end(), [&xml](const urdf::Joint* a, const urdf::Joint* b) {
    return xml.joint_order(a->name) < xml.joint_order(b->name);
  });
  for (const urdf::Joint* joint : joints) {
    if (!parent_.emplace(joint->child_link_name, joint).second) {
      throw InputError(xml.file(), UrdfXml::line(xml.joint(joint->name)),
                       "each link to be the child of at most one joint",
                       "link '" + joint->child_link_name + "' is the child of two joints");
    }
    children_[joint->parent_link_name].push_back(joint);
  }
  root_ = model.getRoot() != nullptr ? model.getRoot()->name : "";
  if (!has_link(root_)) throw InputError(xml.file(), 0, "a root link", "none");
  visit(root_, 0);
  const std::set<std::string> reached(order_.begin(), order_.end());
  for (const auto& [name, children] : children_) {
    if (reached.count(name) == 0) {
      throw InputError(xml.file(), UrdfXml::line(xml.link(name)),
                       "every link connected to the root link '" + root_ + "'",
                       "link '" + name + "' is not");
    }
  }
}

void UrdfTree::visit(const std::string& link, int depth) {
  if (depth > static_cast<int>(children_.size())) return;  // unreachable after the checks
  order_.push_back(link);
  for (const urdf::Joint* joint : children_.at(link)) visit(joint->child_link_name, depth + 1);
}

const urdf::Joint* UrdfTree::parent_joint(const std::string& link) const {
  const auto it = parent_.find(link);
  return it == parent_.end() ? nullptr : it->second;
}

const std::vector<const urdf::Joint*>& UrdfTree::child_joints(const std::string& link) const {
  return children_.at(link);
}

std::vector<const urdf::Joint*> UrdfTree::joints_from_root(const std::string& link) const {
  std::vector<const urdf::Joint*> joints;
  for (const urdf::Joint* j = parent_joint(link); j != nullptr; j = parent_joint(j->parent_link_name)) {
    joints.push_back(j);
  }
  std::reverse(joints.begin(), joints.end());
  return joints;
}

bool is_movable(const urdf::Joint& joint) {
  return joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS ||
         joint.type == urdf::Joint::PRISMATIC;
}

}  // namespace grpvss::io
