#include "claim_check.hpp"

#include <string>
#include <vector>

#include "grpvss/exact/exact_contact.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::certify {
namespace {

// Two hulls of a self-collision pair meet at the placement `placed`, decided exactly.
bool self_collides_exactly(const CheckedCell& cell,
                           const std::vector<std::vector<Eigen::Vector3d>>& placed,
                           CheckLedger& ledger) {
  for (const auto& [a, b] : cell.self_pairs()) {
    ledger.decided();
    if (geometry::classify_exact(placed[static_cast<std::size_t>(a)],
                                 placed[static_cast<std::size_t>(b)]) !=
        geometry::Contact::kSeparated) {
      return true;
    }
  }
  return false;
}

// The robot at `q` touches some obstacle or itself, decided exactly on its raw hulls.
bool collides_exactly(const CheckedCell& cell, const Eigen::VectorXd& q, CheckLedger& ledger) {
  kinematics::Workspace workspace(cell.robot());
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  std::vector<std::vector<Eigen::Vector3d>> placed_hulls(cell.hulls().size());
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    const CheckedHull& hull = cell.hulls()[i];
    kinematics::place_points(workspace.X_WL[hull.link], hull.raw_L, placed_hulls[i]);
  }
  if (self_collides_exactly(cell, placed_hulls, ledger)) return true;
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    const CheckedHull& hull = cell.hulls()[i];
    const std::vector<Eigen::Vector3d>& placed = placed_hulls[i];
    for (std::size_t o = 0; o < cell.obstacles().size(); ++o) {
      if (cell.contact_allowed(hull.link, hull.hull, static_cast<int>(o))) continue;
      ledger.decided();
      if (geometry::classify_exact(placed, cell.obstacles()[o]) != geometry::Contact::kSeparated) {
        return true;
      }
    }
  }
  return false;
}

void check_safety_claim(const Certificate& header, const ClaimFacts& facts, CheckLedger& ledger) {
  const std::string claim = to_string(header.claim);
  const bool clear = header.claim == Verdict::kClear;
  if (!facts.coverage_complete) {
    ledger.fail("claim " + claim + ", but the steps do not cover the whole path");
  }
  if (!facts.all_transitions_certified) {
    ledger.fail("claim " + claim + ", but some transition is not certified");
  }
  if (clear && facts.any_expanded_interference) {
    ledger.fail("claim CLEAR, but the expanded robot interferes");
  }
  if (facts.any_raw_collision) ledger.fail("claim " + claim + ", but the robot collides");
  if (clear && !header.errors.empty()) ledger.fail("claim CLEAR, but the path has errors");
  // Claim `motion`: a transition keeping less than Delta is WITHIN_TOLERANCE too.
  const bool short_of_motion_claim =
      header.clear_claim == ClearClaim::kMotion && facts.any_tolerance_shortfall;
  if (!clear && !facts.any_expanded_interference && !short_of_motion_claim) {
    ledger.fail("claim WITHIN_TOLERANCE, but nothing interferes and every transition keeps the "
                "tolerance");
  }
}

}  // namespace

void check_claim(const Certificate& header, const ClaimFacts& facts, const CheckedCell& cell,
                 CheckLedger& ledger) {
  switch (header.claim) {
    case Verdict::kClear:
    case Verdict::kWithinTolerance:
      check_safety_claim(header, facts, ledger);
      return;
    case Verdict::kCollision: {
      // A wrong joint count at that step was already rejected; it proves nothing here.
      const bool proven = facts.collision_step_q &&
                          facts.collision_step_q->size() == cell.robot().joint_count() &&
                          collides_exactly(cell, *facts.collision_step_q, ledger);
      if (!proven) ledger.fail("claim COLLISION, but the robot at the named step touches no obstacle");
      return;
    }
    case Verdict::kUndecided:
    case Verdict::kError:
      return;
  }
}

}  // namespace grpvss::certify
