#pragma once
/// \file
/// \brief The certified verdict of single configurations: what a motion planner asks of every
/// sample ("is this state valid?"), answered with the certified mode's guarantee. Each term
/// (link hull and obstacle, self pair) is settled by the first slab proven with a positive gap,
/// not by its closest witness: a verdict needs no clearance radius.
/// proof: proofs/configuration-check.md#lemma-configuration-verdict

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// \brief One term that keeps a configuration from CLEAR.
struct ConfigurationFinding {
  enum class Kind {
    kCollision,        ///< the raw link hull meets the obstacle
    kWithinTolerance,  ///< only the hull expanded by the tolerance meets it; the raw hull is clear
    kSelfCollision,    ///< the two raw hulls of a self pair meet
    /// Neither a proven gap nor a contact: a gap below the rounding of the placed hulls
    /// (~1e-15 of their size), of a self pair or of the raw hull of an interfering pair.
    kUndecided,
  };
  Kind kind = Kind::kCollision;
  int link = 0;         ///< 0..N
  int hull = 0;         ///< index within the link
  int obstacle = -1;    ///< index within the environment; -1 for a self pair
  int other_link = -1;  ///< a self pair's upper link; -1 for an obstacle
  int other_hull = -1;
};

/// \brief How reports name a finding: "forearm_link / post: collision", "wrist_3_link /
/// upper_arm_link: self-collision" (hull_label, obstacle_label; the kind as in to_string below).
std::string describe(const ConfigurationFinding& finding, const RobotModel& robot,
                     const Environment& environment);

/// "collision", "within tolerance", "self-collision", "undecided".
std::string to_string(ConfigurationFinding::Kind kind);

/// \brief A configuration's verdict: kClear, kWithinTolerance, kCollision or kUndecided (the
/// worst of its findings: collision, undecided, within tolerance), and every finding in link,
/// hull, obstacle (self pairs after the obstacles) order.
struct ConfigurationVerdict {
  Verdict verdict = Verdict::kClear;
  std::vector<ConfigurationFinding> findings;
};

/// \brief Checks configurations against one cell. Keeps each term's last witness as the next
/// configuration's first try, so consecutive nearby configurations (a planner's edge, a
/// trajectory's samples) are cheapest. Not thread-safe: one per thread; the cell is shared.
class ConfigurationCheck {
 public:
  explicit ConfigurationCheck(const RobotCell& cell);
  ~ConfigurationCheck();
  ConfigurationCheck(ConfigurationCheck&&) noexcept;
  ConfigurationCheck& operator=(ConfigurationCheck&&) noexcept;

  /// \throws std::invalid_argument when q has not the robot's joint count or a value is not
  /// finite (joint limits are the caller's: a planner samples within them).
  ConfigurationVerdict check(const Eigen::VectorXd& q);

 private:
  struct Workspace;
  const RobotCell* cell_;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace grpvss::certify
