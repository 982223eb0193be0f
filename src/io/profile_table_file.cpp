#include "grpvss/io/profile_table_file.hpp"

#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "number_reader.hpp"

namespace grpvss::io {
namespace {

constexpr int kMaxJoints = 64;

std::string show(double x) { return fmt::format("{}", x); }

/// Fritsch-Carlson: a cubic Hermite piece with secant slope delta and end slopes m0, m1 >= 0
/// is monotone when m0 = m1 = 0 for a flat piece, else (m0/delta)^2 + (m1/delta)^2 <= 9.
bool monotone_piece(double delta, double m0, double m1) {
  if (delta == 0.0) return m0 == 0.0 && m1 == 0.0;
  const double alpha = m0 / delta, beta = m1 / delta;
  return alpha * alpha + beta * beta <= 9.0;
}

}  // namespace

ProfileTableData parse_profile_table(std::string_view text, std::string file_name) {
  NumberReader reader(text, file_name);
  ProfileTableData table;
  table.file_name = std::move(file_name);
  const auto joints = reader.read_keyword_integer("joints", "the joint count", 1, kMaxJoints);
  if (!joints) reader.fail(reader.line() + 1, "a header line 'joints N'");
  table.header_line = reader.line();
  table.joint_count = static_cast<int>(*joints);
  const int n = table.joint_count;
  const std::size_t width = 1 + 2 * static_cast<std::size_t>(n);
  std::vector<int> lines;
  while (!reader.at_end()) {
    const NumberLine numbers =
        reader.read_numbers(width, fmt::format("a row 'time, s_1, ds_1, ..., s_{0}, ds_{0}'", n));
    ProfileTableData::Row row;
    row.time = numbers.values[0];
    for (int j = 0; j < n; ++j) {
      const double s = numbers.values[1 + 2 * j], ds = numbers.values[2 + 2 * j];
      if (s < 0.0 || s > 1.0)
        reader.fail(numbers.line, fmt::format("progress s_{} in [0, 1]", j + 1), show(s));
      if (ds < 0.0)
        reader.fail(numbers.line, fmt::format("progress rate ds_{}/dt >= 0", j + 1), show(ds));
      row.s.push_back(s);
      row.ds.push_back(ds);
    }
    const bool first = table.rows.empty();
    if (first && row.time != 0.0) reader.fail(numbers.line, "the first row at time 0", show(row.time));
    if (!first) {
      const ProfileTableData::Row& previous = table.rows.back();
      if (!(row.time > previous.time))
        reader.fail(numbers.line, fmt::format("a time greater than {}", show(previous.time)),
                    show(row.time));
      const double h = row.time - previous.time;
      for (int j = 0; j < n; ++j) {
        if (row.s[j] < previous.s[j])
          reader.fail(numbers.line, fmt::format("non-decreasing progress s_{} (>= {})", j + 1,
                                                show(previous.s[j])),
                      show(row.s[j]));
        if (!monotone_piece((row.s[j] - previous.s[j]) / h, previous.ds[j], row.ds[j]))
          reader.fail(numbers.line,
                      fmt::format("rates ds_{}/dt that keep the Hermite interpolant from line {} "
                                  "monotone (Fritsch-Carlson: (m0/delta)^2 + (m1/delta)^2 <= 9, "
                                  "both 0 on a flat piece)",
                                  j + 1, lines.back()),
                      fmt::format("{} and {}", show(previous.ds[j]), show(row.ds[j])));
      }
    } else {
      for (int j = 0; j < n; ++j)
        if (row.s[j] != 0.0)
          reader.fail(numbers.line, fmt::format("s_{} = 0 in the first row", j + 1), show(row.s[j]));
    }
    table.rows.push_back(std::move(row));
    lines.push_back(numbers.line);
  }
  if (table.rows.size() < 2)
    reader.fail(reader.end_line(), "at least two rows (time 0 and the end of the move)",
                "end of file");
  const ProfileTableData::Row& last = table.rows.back();
  for (int j = 0; j < n; ++j)
    if (last.s[j] != 1.0)
      reader.fail(lines.back(), fmt::format("s_{} = 1 in the last row", j + 1), show(last.s[j]));
  return table;
}

ProfileTableData read_profile_table_file(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError(path, 0, "a readable motion-time table file");
  std::ostringstream text;
  text << stream.rdbuf();
  return parse_profile_table(text.str(), path);
}

}  // namespace grpvss::io
