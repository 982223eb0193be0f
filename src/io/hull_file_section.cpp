#include "hull_file_section.hpp"

#include <algorithm>
#include <optional>

#include "affine_dimension.hpp"

namespace grpvss::io {
namespace {

const char* degeneracy_name(int dimension) {
  switch (dimension) {
    case 0: return "coincident";
    case 1: return "collinear";
    default: return "coplanar";
  }
}

std::string too_many_points() {
  return "at most " + std::to_string(kMaxPointsPerFile) + " hull points in the file";
}

}  // namespace

std::vector<HullPoints> read_hull_list(NumberReader& reader, long long count,
                                       const std::string& owner, PointBudget& budget) {
  std::vector<HullPoints> hulls;
  // count is at most kMaxHullsPerList (checked by the caller); reserve no more than a few.
  hulls.reserve(static_cast<std::size_t>(std::min<long long>(count, 1024)));
  for (long long h = 1; h <= count; ++h) {
    const std::string hull_name = "hull " + std::to_string(h) + " of " + owner;
    const std::optional<long long> declared = reader.read_keyword_integer(
        "HULL", "the number of points of " + hull_name, 4, kMaxPointsPerFile);
    // A declared count is checked against the budget before anything is allocated.
    if (declared && budget.used + *declared > kMaxPointsPerFile) {
      reader.fail(reader.line(), too_many_points(), std::to_string(budget.used + *declared) +
                                                        " points by the end of " + hull_name);
    }
    const long long point_count = declared.value_or(kThesisPointsPerHull);

    HullPoints hull;
    hull.points.reserve(static_cast<std::size_t>(point_count));
    for (long long j = 1; j <= point_count; ++j) {
      const NumberLine row =
          reader.read_numbers(3, "point " + std::to_string(j) + " of " + hull_name + " (x, y, z)");
      if (++budget.used > kMaxPointsPerFile) {
        reader.fail(row.line, too_many_points(), "point " + std::to_string(budget.used));
      }
      if (j == 1) hull.source_line = row.line;
      hull.points.emplace_back(row.values[0], row.values[1], row.values[2]);
    }
    const int dimension = affine_dimension(hull.points);
    if (dimension != 3) {
      reader.fail(hull.source_line,
                  hull_name + " to span 3-D (four points not in one plane)",
                  "all " + std::to_string(point_count) + " points " + degeneracy_name(dimension));
    }
    hulls.push_back(std::move(hull));
  }
  return hulls;
}

}  // namespace grpvss::io
