// certificate_names(): a cell's link and obstacle names for the certificate, none for thesis
// files; their JSON form read back, malformed forms refused; a certificate without names is
// written as before (no "names" member).
#include "grpvss/evidence/certificate_names.hpp"

#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {
namespace {

using nlohmann::json;

HullPoints hull() { return {{Eigen::Vector3d::Zero()}, 0, ""}; }

RobotModel robot_with_link_names(std::vector<std::string> names) {
  RobotModel robot;
  for (const std::string& name : names) {
    Link link;
    link.name = name;
    robot.links.push_back(link);
  }
  return robot;
}

Environment environment_with_names(std::vector<std::string> names, int hulls) {
  Environment environment;
  for (int i = 0; i < hulls; ++i) environment.obstacles.push_back(hull());
  environment.names = std::move(names);
  return environment;
}

TEST(CertificateNames, ACellHasEveryLinkNameAndEveryObstacleHullLabel) {
  const RobotModel robot = robot_with_link_names({"", "base_link", "link_1"});
  const Environment environment = environment_with_names({"table", "fixture", "fixture"}, 3);
  const CertificateNames names = certificate_names(robot, environment);
  EXPECT_EQ(names.links, (std::vector<std::string>{"", "base_link", "link_1"}));
  EXPECT_EQ(names.obstacles,
            (std::vector<std::string>{"table", "fixture piece 0", "fixture piece 1"}));
}

TEST(CertificateNames, ThesisFilesHaveNoNames) {
  const CertificateNames names =
      certificate_names(robot_with_link_names({"", ""}), environment_with_names({}, 2));
  EXPECT_TRUE(names.empty());
  Certificate certificate;
  certificate.names = names;
  EXPECT_FALSE(certificate_to_json(certificate).contains("names"));
}

TEST(CertificateNames, TheJsonFormReadsBackAndTheCertificateCarriesIt) {
  CertificateNames names;
  names.links = {"", "base_link"};
  names.obstacles = {"post"};
  const json value = certificate_names_to_json(names);
  EXPECT_EQ(value, json::parse(R"({"links": ["", "base_link"], "obstacles": ["post"]})"));
  EXPECT_EQ(certificate_names_from_json(value, "c.json"), names);
  Certificate certificate;
  certificate.names = names;
  EXPECT_EQ(certificate_to_json(certificate).at("names"), value);
  // Only the obstacles named: the links list is left out, and read back empty.
  CertificateNames obstacles_only;
  obstacles_only.obstacles = {"post"};
  EXPECT_EQ(certificate_names_to_json(obstacles_only), json::parse(R"({"obstacles": ["post"]})"));
  EXPECT_EQ(certificate_names_from_json(certificate_names_to_json(obstacles_only), "c"),
            obstacles_only);
}

TEST(CertificateNames, MalformedNamesAreInputErrorsNamingTheFile) {
  for (const char* text : {R"([])", R"({"links": "base"})", R"({"links": [1]})",
                           R"({"obstacles": [null]})", R"({"hulls": []})"}) {
    try {
      certificate_names_from_json(json::parse(text), "c.json");
      ADD_FAILURE() << "accepted " << text;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), "c.json") << text;
    }
  }
}

}  // namespace
}  // namespace grpvss::certify
