#pragma once
/// \file
/// \brief Static obstacles (convex hulls in the world frame W) and the thesis's two
/// environment constants used by its step rule (Eq. 3-3).

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "grpvss/model/hull_points.hpp"

namespace grpvss {

/// \brief A robot hull (link, hull index in the link) whose contact with an obstacle hull is
/// allowed: never verified, listed in every report and bound into the certificate.
struct AllowedContactPair {
  int link = 0;
  int hull = 0;
  int obstacle = 0;
  friend bool operator<(const AllowedContactPair& a, const AllowedContactPair& b) {
    return std::tie(a.link, a.hull, a.obstacle) < std::tie(b.link, b.hull, b.obstacle);
  }
  friend bool operator==(const AllowedContactPair& a, const AllowedContactPair& b) {
    return std::tie(a.link, a.hull, a.obstacle) == std::tie(b.link, b.hull, b.obstacle);
  }
};

struct Environment {
  double smallest_angle = 0.0;      ///< theta of Eq. 3-1, RADIANS, 0 < theta < pi
  double smallest_thickness = 0.0;  ///< L of Eq. 3-2, length units
  std::vector<HullPoints> obstacles;  ///< points in the world frame W
  /// names[i]: the name of the obstacle that hull i belongs to (a cell file's `name`; every
  /// convex piece of one named shape carries that name). Empty for thesis environment files,
  /// whose obstacles are known by their index only; otherwise one entry per hull.
  std::vector<std::string> names;
  /// Bound on the distance from every exact obstacle point to the stored hull (length
  /// units): 0 for thesis files (their points are the obstacles); poses, unit conversion and
  /// mesh arithmetic round. proof: proofs/cell-geometry.md#lemma-geometry-error
  double point_error = 0.0;

  /// Robot hull / obstacle pairs whose contact is allowed (a cell's `allowed_contacts`),
  /// sorted and unique. Empty for thesis files.
  std::vector<AllowedContactPair> allowed_contacts;

  /// True when the contact of hull `hull` of link `link` with obstacle `obstacle` is allowed.
  bool contact_allowed(int link, int hull, int obstacle) const {
    return std::binary_search(allowed_contacts.begin(), allowed_contacts.end(),
                              AllowedContactPair{link, hull, obstacle});
  }

  /// True when every hull has a name (names.size() == obstacles.size()).
  bool has_names() const { return !obstacles.empty() && names.size() == obstacles.size(); }
};

/// \brief How reports call hull `index` of `environment`: its name ("table"), the name and
/// the piece when its shape has several convex pieces ("fixture piece 2", counted from 0
/// within the shape), and "obstacle 3" when the environment has no names.
inline std::string obstacle_label(const Environment& environment, int index) {
  const auto i = static_cast<std::size_t>(index);
  if (index < 0 || !environment.has_names() || i >= environment.names.size()) {
    return "obstacle " + std::to_string(index);
  }
  const std::string& name = environment.names[i];
  std::size_t first = i;
  while (first > 0 && environment.names[first - 1] == name) --first;
  std::size_t end = i + 1;
  while (end < environment.names.size() && environment.names[end] == name) ++end;
  if (end - first == 1) return name;
  return name + " piece " + std::to_string(i - first);
}

}  // namespace grpvss
