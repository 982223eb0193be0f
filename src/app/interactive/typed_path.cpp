#include "interactive/typed_path.hpp"

#include <fmt/core.h>

#include "grpvss/io/path_file.hpp"

namespace grpvss::app::interactive {

std::string path_file_text(const std::vector<TypedSegment>& segments) {
  // fmt's "{}" prints the shortest text that reads back as the same double.
  std::string text = fmt::format("{}\n", segments.size());
  for (const TypedSegment& segment : segments) {
    text += fmt::format("{}\n", segment.kind);
    if (segment.kind == 1) {
      for (std::size_t j = 0; j < segment.joint_targets.size(); ++j) {
        text += fmt::format("{},{}\n", segment.joint_targets[j], segment.velocities[j]);
      }
      continue;
    }
    const auto& p = segment.pose;
    text += fmt::format("{},{},{},{},{},{},{}\n", p[0], p[1], p[2], p[3], p[4], p[5], p[6]);
    if (segment.kind == 2) {
      for (double velocity : segment.velocities) text += fmt::format("{}\n", velocity);
    }
  }
  return text;
}

PathProgram typed_program(const std::vector<TypedSegment>& segments, const RobotModel& robot) {
  return io::parse_path_file(path_file_text(segments), "typed path", robot);
}

}  // namespace grpvss::app::interactive
