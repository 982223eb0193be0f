#include "support/urdf_reference.hpp"

#include <sstream>
#include <stdexcept>

#include <tinyxml2.h>

namespace grpvss::test {
namespace {

std::string xml_attribute(const tinyxml2::XMLElement* element, const char* name, const std::string& otherwise) {
  const char* value = element != nullptr ? element->Attribute(name) : nullptr;
  return value != nullptr ? value : otherwise;
}

ReferenceJoint read_joint(const tinyxml2::XMLElement& e) {
  ReferenceJoint joint;
  joint.name = xml_attribute(&e, "name", "");
  joint.type = xml_attribute(&e, "type", "");
  joint.parent = xml_attribute(e.FirstChildElement("parent"), "link", "");
  joint.child = xml_attribute(e.FirstChildElement("child"), "link", "");
  joint.xyz = xml_attribute(e.FirstChildElement("origin"), "xyz", "0 0 0");
  joint.rpy = xml_attribute(e.FirstChildElement("origin"), "rpy", "0 0 0");
  joint.axis = xml_attribute(e.FirstChildElement("axis"), "xyz", "1 0 0");
  if (const tinyxml2::XMLElement* limit = e.FirstChildElement("limit")) {
    joint.lower = limit->DoubleAttribute("lower", 0.0);
    joint.upper = limit->DoubleAttribute("upper", 0.0);
  }
  if (const tinyxml2::XMLElement* mimic = e.FirstChildElement("mimic")) {
    joint.mimic = xml_attribute(mimic, "joint", "");
    joint.multiplier = xml_attribute(mimic, "multiplier", "1");
    joint.offset = xml_attribute(mimic, "offset", "0");
  }
  return joint;
}

ReferenceCollision read_collision(const tinyxml2::XMLElement& e, const std::string& link, int index) {
  ReferenceCollision collision;
  collision.link = link;
  collision.index = index;
  collision.xyz = xml_attribute(e.FirstChildElement("origin"), "xyz", "0 0 0");
  collision.rpy = xml_attribute(e.FirstChildElement("origin"), "rpy", "0 0 0");
  const tinyxml2::XMLElement* shape = e.FirstChildElement("geometry")->FirstChildElement();
  collision.shape = shape->Name();
  collision.size = xml_attribute(shape, "size", "");
  collision.radius = xml_attribute(shape, "radius", "");
  collision.length = xml_attribute(shape, "length", "");
  return collision;
}

}  // namespace

std::vector<std::string> three_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  if (words.size() != 3) throw std::runtime_error("not three numbers: " + text);
  return words;
}

ReferenceUrdf read_reference_urdf(const std::string& path) {
  tinyxml2::XMLDocument document;
  if (document.LoadFile(path.c_str()) != tinyxml2::XML_SUCCESS) {
    throw std::runtime_error("cannot read " + path);
  }
  const tinyxml2::XMLElement* robot = document.RootElement();
  ReferenceUrdf urdf;
  for (const auto* e = robot->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    urdf.joints.push_back(read_joint(*e));
  }
  for (std::size_t j = 0; j < urdf.joints.size(); ++j) urdf.joint_to_child[urdf.joints[j].child] = j;
  for (const auto* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
    const std::string name = xml_attribute(e, "name", "");
    if (urdf.joint_to_child.count(name) == 0) urdf.root = name;
    int index = 0;
    for (const auto* c = e->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision")) {
      urdf.collisions[name].push_back(read_collision(*c, name, index++));
    }
  }
  return urdf;
}

}  // namespace grpvss::test
