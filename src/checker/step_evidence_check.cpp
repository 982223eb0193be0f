#include "step_evidence_check.hpp"

#include <cmath>

#include "grpvss/exact/exact_contact.hpp"

namespace grpvss::certify {

StepEvidenceCheck::StepEvidenceCheck(const CheckedCell& cell, const Certificate& header,
                                     CheckLedger& ledger, ClaimFacts& facts)
    : cell_(cell), header_(header), ledger_(ledger), facts_(facts), workspace_(cell.robot()) {}

std::vector<Rational> StepEvidenceCheck::check(
    const StepCertificate& step, const std::string& where,
    std::vector<std::vector<Eigen::Vector3d>>& placed_raw_out) {
  const std::vector<CheckedHull>& hulls = cell_.hulls();
  std::vector<Rational> verified(hulls.size(), Rational(0));
  placed_raw_out.assign(hulls.size(), {});
  if (step.q.size() != cell_.robot().joint_count()) {
    ledger_.fail(where + ": wrong joint count");
    return verified;
  }
  if (step.hulls.size() != hulls.size()) {
    ledger_.fail(where + ": expected a record for each of the " + std::to_string(hulls.size()) +
                 " hulls");
    return verified;
  }
  kinematics::forward_kinematics(cell_.chain(), step.q, workspace_);
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    const CheckedHull& hull = hulls[i];
    const HullRecord& record = step.hulls[i];
    const std::string hull_where = where + " link " + std::to_string(hull.link) + " hull " +
                                   std::to_string(hull.hull);
    if (record.link != hull.link || record.hull != hull.hull) {
      ledger_.fail(hull_where + ": hull records out of order");
      continue;
    }
    const Eigen::Isometry3d& X_WL = workspace_.X_WL[hull.link];
    std::vector<Eigen::Vector3d> placed_expanded, placed_raw;
    kinematics::place_points(X_WL, hull.expanded_L, placed_expanded);
    kinematics::place_points(X_WL, hull.raw_L, placed_raw);
    placed_raw_out[i] = placed_raw;
    const ObstacleProofs proofs = read_evidence(record, placed_expanded, placed_raw, hull_where);
    if (proofs.bad) continue;
    const Rational radius = proven_radius(proofs, record, box_of(placed_expanded), hull_where);
    ledger_.decided();
    if (!(exact(record.radius) <= radius) || record.radius < 0.0) {
      ledger_.fail(hull_where + ": the claimed radius exceeds what the evidence proves");
      continue;
    }
    verified[i] = exact(record.radius);
  }
  return verified;
}

StepEvidenceCheck::ObstacleProofs StepEvidenceCheck::read_evidence(
    const HullRecord& record, const std::vector<Eigen::Vector3d>& placed_expanded,
    const std::vector<Eigen::Vector3d>& placed_raw, const std::string& where) {
  const int obstacle_count = static_cast<int>(cell_.obstacles().size());
  const Rational delta = exact(header_.tolerance);
  const Rational eps = exact(header_.placement_error);
  ObstacleProofs proofs;
  proofs.expanded_radius.resize(obstacle_count);
  proofs.raw_radius.resize(obstacle_count);
  proofs.expanded_interferes.assign(obstacle_count, 0);
  for (const EvidenceRecord& evidence : record.evidence) {
    if (evidence.obstacle < 0 || evidence.obstacle >= obstacle_count) {
      ledger_.fail(where + ": evidence names an obstacle that does not exist");
      proofs.bad = true;
      continue;
    }
    const auto& placed = evidence.expanded ? placed_expanded : placed_raw;
    if (evidence.separated) {
      ledger_.decided();
      if (!geometry::check_witness_exactly(placed, cell_.obstacles()[evidence.obstacle],
                                           evidence.witness, evidence.lower_bound) ||
          !(evidence.lower_bound >= 0.0)) {
        ledger_.fail(where + " obstacle " + std::to_string(evidence.obstacle) +
                     ": the separation witness does not hold");
        proofs.bad = true;
        continue;
      }
      if (evidence.expanded) {
        // proof: proofs/offset-containment.md#clearance-through-offset
        proofs.expanded_radius[evidence.obstacle] = delta + exact(evidence.lower_bound);
      } else {
        const Rational r = exact(evidence.lower_bound) - eps;
        proofs.raw_radius[evidence.obstacle] = r > 0 ? r : Rational(0);
      }
    } else if (evidence.expanded) {
      proofs.expanded_interferes[evidence.obstacle] = 1;
      facts_.any_expanded_interference = true;
    } else {
      facts_.any_raw_collision = true;
    }
  }
  return proofs;
}

Rational StepEvidenceCheck::proven_radius(const ObstacleProofs& proofs, const HullRecord& record,
                                          const Box& placed_box, const std::string& where) {
  std::optional<Rational> radius;
  auto lower_to = [&radius](const Rational& r) {
    if (!radius || r < *radius) radius = r;
  };
  bool beyond_margin = false;  // some obstacle is accounted for by the broadphase margin
  for (std::size_t o = 0; o < cell_.obstacles().size(); ++o) {
    if (cell_.contact_allowed(record.link, record.hull, static_cast<int>(o))) continue;
    if (proofs.expanded_radius[o]) {
      lower_to(*proofs.expanded_radius[o]);
    } else if (proofs.expanded_interferes[o]) {
      // A raw collision or no raw evidence: nothing proven.
      lower_to(proofs.raw_radius[o] ? *proofs.raw_radius[o] : Rational(0));
    } else if (std::isfinite(record.broadphase_margin) && record.broadphase_margin >= 0.0) {
      ledger_.decided();
      if (!boxes_farther_than(placed_box, cell_.obstacle_boxes()[o], record.broadphase_margin)) {
        ledger_.fail(where + " obstacle " + std::to_string(o) +
                     ": no evidence and not beyond the broadphase margin");
        lower_to(Rational(0));
      } else {
        beyond_margin = true;
      }
    } else {
      ledger_.fail(where + " obstacle " + std::to_string(o) + ": no evidence");
      lower_to(Rational(0));
    }
  }
  // Obstacles beyond the margin are farther than Delta + margin from every true point of the
  // hull: one bound for all of them. No obstacle at all: nothing can be hit, any radius up to
  // the probe's cap is vacuously true. proof: proofs/two-ball-cover.md#corollary-step
  if (beyond_margin) lower_to(exact(header_.tolerance) + exact(record.broadphase_margin));
  return radius ? *radius : exact(kUnboundedRadius);
}

}  // namespace grpvss::certify
