#include "trajectory_text.hpp"

#include <fmt/format.h>

#include "grpvss/common/input_error.hpp"
#include "blank_char.hpp"

namespace grpvss::io {
namespace {

constexpr std::size_t kMaxEchoedText = 40;

}  // namespace

std::string_view without_byte_order_mark(std::string_view text) {
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) {
    text.remove_prefix(kByteOrderMark.size());
  }
  return text;
}

std::string_view trim_blanks(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string quoted_text(std::string_view text) {
  std::string result = "'";
  for (const char c : text.substr(0, kMaxEchoedText)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte >= 0x7f) {
      result += fmt::format("\\x{:02x}", byte);
    } else {
      result += c;
    }
  }
  return result + (text.size() > kMaxEchoedText ? "...'" : "'");
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) text += (i > 0 ? separator : "") + items[i];
  return text;
}

std::string format_number(double value) { return fmt::format("{}", value); }

void check_waypoint_time(const JointTrajectory& trajectory, double time, int line,
                         const std::string& what) {
  if (!(time >= 0.0)) {
    throw InputError(trajectory.source_file, line, what + " >= 0 s", format_number(time) + " s");
  }
  if (trajectory.times.empty()) return;
  const double previous = trajectory.times.back();
  if (!(time > previous)) {
    const int k = trajectory.waypoint_count() - 1;
    throw InputError(trajectory.source_file, line,
                     what + " greater than " + format_number(previous) +
                         " s (the time of the previous waypoint, " +
                         describe_waypoint(trajectory, k) + ")",
                     format_number(time) + " s");
  }
}

}  // namespace grpvss::io
