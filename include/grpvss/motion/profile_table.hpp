#pragma once
/// \file
/// \brief User motion-time profiles: GRPVSS's replacement for the thesis's
/// compiled FORTRAN subroutine MOTFIL (Appendix A.1.2). Format: docs/trajectories.md.
///
/// Semantics: for every joint j the table gives its normalised progress \f$s_j(t)\in[0,1]\f$
/// and \f$\dot s_j(t)\f$ against the ABSOLUTE time t (seconds) since the start of a PTP move.
/// A joint moving from q_s to q_f is at \f$q_s + (q_f - q_s)\,s_j(t)\f$ with velocity
/// \f$(q_f - q_s)\,\dot s_j(t)\f$. Between rows, s_j is the cubic Hermite interpolant of the
/// given (s, ds/dt) pairs; the reader checks the Fritsch-Carlson condition so that the
/// interpolant is monotone and stays in [0, 1].

#include <string>
#include <vector>

#include "grpvss/model/profile_table_data.hpp"
#include "grpvss/motion/trapezoid_profile.hpp"

namespace grpvss::motion {

/// \brief Evaluates a validated table (io/profile_table_file.hpp reads one).
class ProfileTable {
 public:
  explicit ProfileTable(ProfileTableData data);

  int joint_count() const { return data_.joint_count; }
  /// Time at which joint j (0-based) first reaches s = 1: its move duration.
  double duration(int joint) const { return durations_[joint]; }
  /// s_j and ds_j/dt at time t (clamped: s = 0 before 0, s = 1 after the joint's duration).
  JointState progress(int joint, double t) const;

  const std::string& file_name() const { return data_.file_name; }
  int header_line() const { return data_.header_line; }  ///< line of the `joints N` header

 private:
  ProfileTableData data_;
  std::vector<double> durations_;
};

}  // namespace grpvss::motion
