#include "grpvss/motion/profile_table.hpp"

#include <algorithm>

namespace grpvss::motion {

ProfileTable::ProfileTable(ProfileTableData data) : data_(std::move(data)) {
  // A joint's move lasts until the first row where its progress reaches 1 (the reader
  // guarantees the last row has s = 1 for every joint).
  for (int j = 0; j < data_.joint_count; ++j) {
    const auto reached = std::find_if(data_.rows.begin(), data_.rows.end(),
                                      [j](const ProfileTableData::Row& row) { return row.s[j] == 1.0; });
    durations_.push_back(reached->time);
  }
}

JointState ProfileTable::progress(int joint, double t) const {
  if (t <= 0.0) return {0.0, 0.0};
  if (t >= durations_[joint]) return {1.0, 0.0};
  // First row strictly after t; t lies in [rows[k-1].time, rows[k].time).
  const auto after = std::upper_bound(data_.rows.begin(), data_.rows.end(), t,
                                      [](double time, const ProfileTableData::Row& row) { return time < row.time; });
  const ProfileTableData::Row& r1 = *after;
  const ProfileTableData::Row& r0 = *(after - 1);
  const double h = r1.time - r0.time;
  const double u = (t - r0.time) / h;
  const double s0 = r0.s[joint], s1 = r1.s[joint], m0 = r0.ds[joint], m1 = r1.ds[joint];
  // Cubic Hermite basis on [0, 1].
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  const double s = h00 * s0 + h10 * h * m0 + h01 * s1 + h11 * h * m1;
  const double d00 = 6 * u * u - 6 * u, d10 = 3 * u * u - 4 * u + 1;
  const double d01 = -d00, d11 = 3 * u * u - 2 * u;
  const double ds = (d00 * s0 + d01 * s1) / h + d10 * m0 + d11 * m1;
  return {std::clamp(s, 0.0, 1.0), ds};
}

}  // namespace grpvss::motion
