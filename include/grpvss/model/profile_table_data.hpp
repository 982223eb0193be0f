#pragma once
/// \file
/// \brief A user motion-time table as read from its file (docs/trajectories.md): GRPVSS's
/// replacement for the thesis's compiled FORTRAN subroutine MOTFIL (Appendix A.1.2). Plain
/// data; io/profile_table_file.hpp reads and validates it, motion::ProfileTable evaluates it.

#include <string>
#include <vector>

namespace grpvss {

/// \brief Rows of (time, s_j, ds_j/dt) for every joint j, as validated by the reader: times
/// strictly increasing from 0, every s_j non-decreasing from 0 to 1 in [0, 1], ds_j >= 0, and
/// every Hermite piece monotone (Fritsch-Carlson).
struct ProfileTableData {
  struct Row {
    double time = 0.0;  ///< s since the start of the PTP move
    std::vector<double> s, ds;  ///< one entry per joint
  };
  std::string file_name;  ///< for messages
  int header_line = 0;    ///< line of the `joints N` header
  int joint_count = 0;
  std::vector<Row> rows;
};

}  // namespace grpvss
