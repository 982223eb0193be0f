// CSV trajectories: `time,<joint>...[,<joint>.vel...]` (docs/trajectories.md, section 9.1).
#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/common/input_error.hpp"
#include "number_reader.hpp"
#include "grpvss/io/trajectory_file.hpp"
#include "trajectory_text.hpp"

namespace grpvss::io {
namespace {

constexpr std::string_view kVelocitySuffix = ".vel";

/// One content line: comment and line end removed, not blank.
struct CsvLine {
  int number = 0;
  std::string_view content;
};

/// Walks the text line by line, skipping blank and comment lines (`#` to the end of a line).
class CsvLines {
 public:
  explicit CsvLines(std::string_view text) : text_(without_byte_order_mark(text)) {}

  /// The next content line; std::nullopt at the end of the text.
  std::optional<CsvLine> next() {
    while (position_ < text_.size()) {
      const std::size_t newline = text_.find('\n', position_);
      const std::size_t stop = newline == std::string_view::npos ? text_.size() : newline;
      std::string_view content = text_.substr(position_, stop - position_);
      const int number = line_++;
      position_ = stop + 1;
      if (const std::size_t hash = content.find('#'); hash != std::string_view::npos) {
        content = content.substr(0, hash);
      }
      content = trim_blanks(content);
      if (!content.empty()) return CsvLine{number, content};
    }
    return std::nullopt;
  }
  /// The line reported for "found end of file": one past the last line.
  int end_line() const { return line_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0;
  int line_ = 1;
};

std::vector<std::string_view> split_fields(std::string_view content) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = content.find(',', start);
    const std::size_t stop = comma == std::string_view::npos ? content.size() : comma;
    fields.push_back(trim_blanks(content.substr(start, stop - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

/// Which column holds what, after the header line.
struct CsvColumns {
  std::vector<std::string> joint_names;    ///< in the order of their position columns
  std::vector<std::size_t> position_column;
  std::vector<std::size_t> velocity_column;  ///< empty when there are no velocities
  std::vector<std::string> column_names;     ///< every column, for messages
};

void check_column_name(std::string_view name, std::size_t column, const std::string& file,
                       int line) {
  const std::string where = " (column " + std::to_string(column + 1) + ")";
  if (name.empty()) throw InputError(file, line, "a column name" + where, "an empty field");
  const bool plain = std::none_of(name.begin(), name.end(), [](char c) {
    return c == '"' || c == '\'' || c == ' ' || c == '\t' || static_cast<unsigned char>(c) < 0x20;
  });
  if (!plain) {
    throw InputError(file, line, "a column name without quotes or blanks" + where, quoted_text(name));
  }
}

void check_unique_columns(const std::vector<std::string_view>& fields, const std::string& file,
                          int line) {
  std::map<std::string_view, std::size_t> first_column;
  for (std::size_t column = 0; column < fields.size(); ++column) {
    const auto [it, inserted] = first_column.emplace(fields[column], column);
    if (!inserted) {
      throw InputError(file, line, "every column named once",
                       quoted_text(fields[column]) + " in columns " + std::to_string(it->second + 1) +
                           " and " + std::to_string(column + 1));
    }
  }
}

/// Velocity column of every joint, or none; a velocity column needs its position column.
void assign_velocity_columns(CsvColumns& columns,
                             const std::map<std::string, std::size_t>& velocity_of,
                             const std::string& file, int line) {
  for (const auto& [joint, column] : velocity_of) {
    if (std::find(columns.joint_names.begin(), columns.joint_names.end(), joint) ==
        columns.joint_names.end()) {
      throw InputError(file, line,
                       "a position column " + quoted_text(joint) + " for the velocity column " +
                           quoted_text(joint + std::string(kVelocitySuffix)),
                       "none");
    }
  }
  if (velocity_of.empty()) return;
  std::vector<std::string> missing;
  for (const std::string& joint : columns.joint_names) {
    const auto it = velocity_of.find(joint);
    if (it == velocity_of.end()) {
      missing.push_back(joint + std::string(kVelocitySuffix));
    } else {
      columns.velocity_column.push_back(it->second);
    }
  }
  if (!missing.empty()) {
    throw InputError(file, line, "a velocity column for every joint or for none",
                     "velocity columns for " + std::to_string(velocity_of.size()) + " of " +
                         std::to_string(columns.joint_names.size()) + " joints (no " +
                         join(missing, ", ") + ")");
  }
}

CsvColumns parse_header(const CsvLine& header, const std::string& file) {
  const std::vector<std::string_view> fields = split_fields(header.content);
  for (std::size_t column = 0; column < fields.size(); ++column) {
    check_column_name(fields[column], column, file, header.number);
  }
  if (fields[0] != "time") {
    throw InputError(file, header.number, "'time' as the first column of the header",
                     quoted_text(fields[0]));
  }
  check_unique_columns(fields, file, header.number);
  CsvColumns columns;
  std::map<std::string, std::size_t> velocity_of;
  for (std::size_t column = 1; column < fields.size(); ++column) {
    const std::string_view name = fields[column];
    if (ends_with(name, kVelocitySuffix) && name.size() > kVelocitySuffix.size()) {
      velocity_of.emplace(std::string(name.substr(0, name.size() - kVelocitySuffix.size())),
                          column);
    } else {
      columns.joint_names.emplace_back(name);
      columns.position_column.push_back(column);
    }
  }
  if (columns.joint_names.empty()) {
    throw InputError(file, header.number, "at least one joint column after 'time'",
                     std::to_string(fields.size()) + " column" + (fields.size() == 1 ? "" : "s"));
  }
  assign_velocity_columns(columns, velocity_of, file, header.number);
  for (std::string_view name : fields) columns.column_names.emplace_back(name);
  return columns;
}

/// The numbers of one row, one per column.
std::vector<double> parse_row(const CsvLine& row, const CsvColumns& columns,
                              const std::string& file) {
  const std::vector<std::string_view> fields = split_fields(row.content);
  const std::size_t expected = columns.column_names.size();
  if (fields.size() != expected) {
    throw InputError(file, row.number,
                     std::to_string(expected) + " comma-separated values (one per header column)",
                     std::to_string(fields.size()) + " value" + (fields.size() == 1 ? "" : "s"));
  }
  std::vector<double> values(expected);
  for (std::size_t column = 0; column < expected; ++column) {
    values[column] = parse_number_field(fields[column], file, row.number,
                                        "column " + quoted_text(columns.column_names[column]));
  }
  return values;
}

void append_waypoint(JointTrajectory& trajectory, const CsvColumns& columns,
                     const std::vector<double>& values, int line) {
  check_waypoint_time(trajectory, values[0], line, "time");
  const auto joints = static_cast<Eigen::Index>(columns.joint_names.size());
  Eigen::VectorXd positions(joints);
  for (Eigen::Index j = 0; j < joints; ++j) positions[j] = values[columns.position_column[j]];
  trajectory.times.push_back(values[0]);
  trajectory.positions.push_back(positions);
  trajectory.source_lines.push_back(line);
  if (columns.velocity_column.empty()) return;
  Eigen::VectorXd velocities(joints);
  for (Eigen::Index j = 0; j < joints; ++j) velocities[j] = values[columns.velocity_column[j]];
  trajectory.velocities.push_back(velocities);
}

}  // namespace

JointTrajectory parse_trajectory_csv(std::string_view text, const std::string& file_name) {
  CsvLines lines(text);
  const std::optional<CsvLine> header = lines.next();
  if (!header) {
    throw InputError(file_name, lines.end_line(), "a header line 'time,<joint names>'",
                     "end of file");
  }
  const CsvColumns columns = parse_header(*header, file_name);
  JointTrajectory trajectory;
  trajectory.source_file = file_name;
  trajectory.format = TrajectoryFormat::kCsv;
  trajectory.joint_names = columns.joint_names;
  trajectory.joint_names_line = header->number;
  while (const std::optional<CsvLine> row = lines.next()) {
    append_waypoint(trajectory, columns, parse_row(*row, columns, file_name), row->number);
  }
  if (trajectory.times.empty()) {
    throw InputError(file_name, lines.end_line(), "at least one waypoint row after the header",
                     "end of file");
  }
  return trajectory;
}

}  // namespace grpvss::io
