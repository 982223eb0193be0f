#pragma once
/// \file
/// \brief The motion model: how the controller moves the robot between the path's targets
/// (PTP timing, user profiles, CP speed and sampling). Part of every run's resolved setup and
/// bound into the certificate: the checker replays the same model (docs/trajectories.md).

#include <memory>
#include <optional>
#include <string_view>

#include <Eigen/Core>

namespace grpvss::motion {

class ProfileTable;

/// \brief How the joints of one PTP move are timed against each other.
enum class PtpTiming {
  /// Every joint runs its own profile with its own v_m, a_m, d_m and stops on its own
  /// (what the thesis's output sample A.3 does). The move lasts as long as the slowest joint.
  kIndependent,
  /// All joints arrive together (the "smooth controller" of Section 1.1.2.1.1): the slowest
  /// joint keeps its profile of duration T; every other joint's profile q_j(t) of duration
  /// T_j is stretched in time, \f$\tilde q_j(t) = q_j(t\,T_j/T)\f$. For a trapezoid this is
  /// exactly the trapezoid with \f$k v_m, k^2 a_m, k^2 d_m\f$, \f$k = T_j/T \le 1\f$: the same
  /// shape, every limit scaled down, so all limits still hold.
  kSynchronized,
};

/// "independent" / "synchronized" (the CLI's and the certificate's spelling).
const char* to_string(PtpTiming timing);
/// The timing spelled `text`, or nullopt.
std::optional<PtpTiming> ptp_timing_from_string(std::string_view text);

struct MotionModel {
  PtpTiming timing = PtpTiming::kIndependent;
  /// User motion-time table replacing the ideal trapezoids (parsed by io/), or null.
  std::shared_ptr<const ProfileTable> table;
  /// Nominal constant Cartesian speed of the end effector on CP lines (length units per s).
  /// The thesis ignores CP velocity (3.2.3.2); GRPVSS times a line of length L as L / speed.
  double cp_speed = 1.0;
  /// Largest path-length spacing of the CP samples (IK check points), length units.
  double cp_spacing = 0.5;
  /// Where the path starts (library units: rad, length), one value per joint, within the
  /// limits (the caller checked it: cell::start_configuration). Unset: the robot's home.
  /// A joint trajectory starts at its first waypoint instead (`--start` must equal it).
  std::optional<Eigen::VectorXd> start;
};

}  // namespace grpvss::motion
