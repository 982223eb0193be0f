#pragma once
// One certificate step: the configuration's hulls are placed by the checker's own forward
// kinematics, every recorded separation witness is decided exactly, every obstacle must be
// accounted for (a witness, a recorded interference, or the broadphase margin), and each hull's
// claimed radius must not exceed what its evidence proves.
// proof: proofs/two-ball-cover.md#corollary-step, proofs/offset-containment.md#clearance-through-offset

#include <string>
#include <vector>

#include "check_ledger.hpp"
#include "checked_cell.hpp"
#include "claim_facts.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::certify {

class StepEvidenceCheck {
 public:
  StepEvidenceCheck(const CheckedCell& cell, const Certificate& header, CheckLedger& ledger,
                    ClaimFacts& facts);

  /// The exactly verified radius of every hull at `step` (0 where the claim is rejected);
  /// `placed_raw` receives each hull's raw vertices placed at the step.
  std::vector<Rational> check(const StepCertificate& step, const std::string& where,
                              std::vector<std::vector<Eigen::Vector3d>>& placed_raw);
  /// The link poses the last check() placed the hulls by (stale where it placed none).
  const std::vector<Eigen::Isometry3d>& link_poses() const { return workspace_.X_WL; }

 private:
  /// Per obstacle, what one hull's evidence proves.
  struct ObstacleProofs {
    std::vector<std::optional<Rational>> expanded_radius, raw_radius;
    std::vector<char> expanded_interferes;
    bool bad = false;  ///< some record names no obstacle or its witness fails
  };
  ObstacleProofs read_evidence(const HullRecord& record,
                               const std::vector<Eigen::Vector3d>& placed_expanded,
                               const std::vector<Eigen::Vector3d>& placed_raw,
                               const std::string& where);
  /// The radius the proofs give the hull, every obstacle accounted for.
  Rational proven_radius(const ObstacleProofs& proofs, const HullRecord& record,
                         const Box& placed_box, const std::string& where);

  const CheckedCell& cell_;
  const Certificate& header_;
  CheckLedger& ledger_;
  ClaimFacts& facts_;
  kinematics::Workspace workspace_;
};

}  // namespace grpvss::certify
