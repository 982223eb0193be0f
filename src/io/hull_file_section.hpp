#pragma once
/// \file
/// \brief Reading a list of hulls (the shared part of the robot and environment files),
/// including the any-vertex-count extension `HULL k`, and the exact "spans 3-D" check.

#include <string>
#include <vector>

#include "number_reader.hpp"
#include "grpvss/model/hull_points.hpp"

namespace grpvss::io {

inline constexpr long long kThesisPointsPerHull = 16;  ///< thesis Figure 7
inline constexpr long long kMaxHullsPerList = 100000;  ///< per NOBAR_i / NOB
inline constexpr long long kMaxPointsPerFile = 1000000;

/// \brief Running total of points read from one file, to fail fast on absurd inputs.
struct PointBudget {
  long long used = 0;
};

/// \brief Reads `count` hulls. Each hull is 16 lines `x, y, z`, or, with the extension, a
/// line `HULL k` (4 <= k <= 10^6) followed by k lines `x, y, z`. Every hull must span 3-D
/// (exact test, see affine_dimension.hpp); otherwise the error names the hull's first line.
/// \param owner names the list for messages, e.g. "link 2" or "the environment".
std::vector<HullPoints> read_hull_list(NumberReader& reader, long long count,
                                       const std::string& owner, PointBudget& budget);

}  // namespace grpvss::io
