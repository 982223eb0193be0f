#pragma once
// The URDF's XML as tinyxml2 reads it, beside urdfdom's model: line numbers for messages, the
// document order of joints, and the few attributes whose decimals urdfdom does not keep
// (`<origin rpy>` becomes a quaternion there) or that GRPVSS must read exactly
// (proof: proofs/urdf-frames.md#decimal-inputs). Private to src/io.

#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <tinyxml2.h>

namespace grpvss::io {

/// Smallest nonzero and largest magnitude GRPVSS accepts for a number of a robot description:
/// the double nearest to such a decimal is within a relative 2^-53 of it.
inline constexpr double kSmallestDescriptionMagnitude = 1e-300;
inline constexpr double kLargestDescriptionMagnitude = 1e9;

/// Three numbers separated by blanks, each finite with 0 or a magnitude within
/// [kSmallestDescriptionMagnitude, kLargestDescriptionMagnitude]; nullopt otherwise.
std::optional<Eigen::Vector3d> parse_three_numbers(std::string_view text);
/// One such number; nullopt otherwise.
std::optional<double> parse_one_number(std::string_view text);
/// True when `x` is 0 or within the accepted magnitudes.
bool is_accepted_magnitude(double x);

class UrdfXml {
 public:
  /// Parses `text`; InputError(file, line, ...) when it is not well-formed XML or has no
  /// `<robot>` root element.
  UrdfXml(std::string_view text, std::string file);

  const std::string& file() const { return file_; }
  /// The first `<joint>` / `<link>` child of `<robot>` with this name; nullptr when none.
  const tinyxml2::XMLElement* joint(const std::string& name) const;
  const tinyxml2::XMLElement* link(const std::string& name) const;
  /// The first `<joint>` child of `<robot>` (walk on with NextSiblingElement("joint")).
  const tinyxml2::XMLElement* first_joint() const { return first_joint_; }
  /// Position of the joint among the `<joint>` elements (document order); -1 when unknown.
  int joint_order(const std::string& name) const;
  /// The `index`-th `<collision>` child of the link's element; nullptr when none.
  const tinyxml2::XMLElement* collision(const std::string& link, int index) const;

  /// Line of an element (0 for nullptr).
  static int line(const tinyxml2::XMLElement* element);
  /// The `rpy` of `element`'s first `<origin>` child (0 0 0 when absent); InputError when it
  /// is not three accepted numbers. `owner` names the element in messages.
  Eigen::Vector3d origin_rpy(const tinyxml2::XMLElement& element, const std::string& owner) const;
  /// A numeric attribute of `element` (default when absent); InputError when malformed.
  double number_attribute(const tinyxml2::XMLElement& element, const char* attribute,
                          double default_value, const std::string& owner) const;

 private:
  std::string file_;
  tinyxml2::XMLDocument document_;
  const tinyxml2::XMLElement* first_joint_ = nullptr;
  std::map<std::string, const tinyxml2::XMLElement*> joints_;
  std::map<std::string, int> joint_order_;
  std::map<std::string, const tinyxml2::XMLElement*> links_;
};

}  // namespace grpvss::io
