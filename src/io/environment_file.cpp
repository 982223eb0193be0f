#include "grpvss/io/environment_file.hpp"

#include <fmt/format.h>

#include "hull_file_section.hpp"
#include "number_reader.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io {

Environment parse_environment_file(std::string_view text, const std::string& file_name) {
  NumberReader reader(text, file_name);
  Environment environment;

  const double angle_degrees =
      reader.read_number("the smallest angle theta of the obstacles (degrees)");
  if (!(angle_degrees > 0.0 && angle_degrees < 180.0)) {
    reader.fail(reader.line(), "a smallest angle theta strictly between 0 and 180 degrees",
                fmt::format("{}", angle_degrees));
  }
  environment.smallest_angle = degrees_to_radians(angle_degrees);

  environment.smallest_thickness =
      reader.read_number("the smallest thickness L of the obstacles");
  if (!(environment.smallest_thickness > 0.0)) {
    reader.fail(reader.line(), "a positive smallest thickness L",
                fmt::format("{}", environment.smallest_thickness));
  }

  const long long hull_count =
      reader.read_integer("the number of obstacle hulls NOB", 0, kMaxHullsPerList);
  PointBudget budget;
  environment.obstacles = read_hull_list(reader, hull_count, "the environment", budget);
  reader.expect_end("the last obstacle hull");
  return environment;
}

Environment read_environment_file(const std::string& path) {
  return parse_environment_file(read_text_file(path), path);
}

}  // namespace grpvss::io
