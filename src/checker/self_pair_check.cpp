#include "self_pair_check.hpp"

#include <algorithm>

#include <fmt/core.h>

#include "grpvss/exact/exact_contact.hpp"
#include "revolution_check.hpp"

namespace grpvss::certify {
namespace {

std::string pair_where(const CheckedCell& cell, std::size_t p, const std::string& where) {
  return where + " self pair " + self_pair_label(cell.robot(), cell.robot().self_collision_pairs[p]);
}

// The gap g = max((d_k + d_{k+1} - M)/2, max(d_k, d_{k+1}) - M), at least 0, exactly.
// proof: proofs/two-ball-cover.md#corollary-self-tolerance-along-motion
Rational kept_gap(const Rational& distance_from, const Rational& distance_to, const Rational& bound) {
  const Rational balanced = (distance_from + distance_to - bound) / 2;
  const Rational one_sided = std::max(distance_from, distance_to) - bound;
  return std::max(Rational(0), std::max(balanced, one_sided));
}

// Claim `motion`: the pair keeps a gap of at least Delta; a CLEAR certificate that rests on
// less is rejected, and any shortfall makes WITHIN_TOLERANCE consistent (claim_check.cpp).
void hold_gap_to_tolerance(const CheckedCell& cell, const Certificate& header, std::size_t p,
                           const Rational& kept, CheckLedger& ledger, ClaimFacts& facts,
                           const std::string& where) {
  const Rational tolerance = exact(header.tolerance);
  if (kept < tolerance) facts.any_tolerance_shortfall = true;
  if (header.claim != Verdict::kClear || header.clear_claim != ClearClaim::kMotion) return;
  ledger.decided();
  if (kept >= tolerance) return;
  ledger.fail(fmt::format("{}: the gap kept along the motion {:.6g} is below the tolerance {} "
                          "(claim motion: robot + tolerance clear of itself along the whole "
                          "motion)",
                          pair_where(cell, p, where), kept.get_d(), header.tolerance));
}

}  // namespace

SelfPairDistances check_self_pair_evidence(
    const CheckedCell& cell, const Certificate& header, const StepCertificate& step,
    const std::vector<std::vector<Eigen::Vector3d>>& placed_raw,
    const std::vector<Eigen::Isometry3d>& X_WL, CheckLedger& ledger, const std::string& where) {
  const auto& pairs = cell.self_pairs();
  SelfPairDistances distances{std::vector<Rational>(pairs.size(), Rational(0)),
                              std::vector<Rational>(pairs.size(), Rational(0))};
  if (pairs.empty()) return distances;
  if (step.self_pairs.size() != pairs.size()) {
    ledger.fail(where + ": expected a self-pair record for each of the " +
                std::to_string(pairs.size()) + " self-collision pairs");
    return distances;
  }
  const Rational twice_error = 2 * exact(header.placement_error);
  // proof: proofs/cell-geometry.md#lemma-geometry-error (each hull within eps of its exact place)
  const auto less_placement = [&](double lower_bound) {
    const Rational d = exact(lower_bound) - twice_error;
    return d > 0 ? d : Rational(0);
  };
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const SelfPairRecord& record = step.self_pairs[p];
    const auto& a = placed_raw[static_cast<std::size_t>(pairs[p].first)];
    const auto& b = placed_raw[static_cast<std::size_t>(pairs[p].second)];
    if (!record.separated || a.empty() || b.empty()) continue;  // nothing proven: d = 0
    ledger.decided();
    if (!(record.lower_bound >= 0.0) ||
        !geometry::check_witness_exactly(a, b, record.witness, record.lower_bound)) {
      ledger.fail(pair_where(cell, p, where) + ": the separation witness does not hold");
      continue;
    }
    distances.relative[p] = less_placement(record.lower_bound);
    if (record.revolution_lower_bound == 0.0) continue;
    // The slab's side at hull b holds (above); the solid must lie on the other side.
    // proof: proofs/two-ball-cover.md#revolution-route
    ledger.decided();
    const CheckedHull& hull_a = cell.hulls()[static_cast<std::size_t>(pairs[p].first)];
    if (!hull_a.revolution_L || static_cast<std::size_t>(hull_a.link) >= X_WL.size() ||
        !solid_side_holds_exactly(*hull_a.revolution_L, X_WL[static_cast<std::size_t>(hull_a.link)],
                                     record.witness, record.revolution_lower_bound)) {
      ledger.fail(pair_where(cell, p, where) +
                  ": the distance from the solid of revolution does not hold");
      continue;
    }
    distances.revolution[p] = less_placement(record.revolution_lower_bound);
  }
  return distances;
}

// proof: proofs/two-ball-cover.md#lemma-relative-motion
void check_self_pair_transition(const CheckedCell& cell, const Certificate& header,
                                const StepCertificate& from, const StepCertificate& to,
                                const TransitionRecord& claimed,
                                const std::vector<std::optional<Rational>>& hull_bounds,
                                const SelfPairBounds& bounds, const VertexRouteBound& vertex_bound,
                                const SelfPairDistances& distance_from,
                                const SelfPairDistances& distance_to, CheckLedger& ledger,
                                ClaimFacts& facts, const std::string& where) {
  const auto& pairs = cell.self_pairs();
  const int joints = cell.robot().joint_count();
  const bool configurations_usable = from.q.size() == joints && to.q.size() == joints;
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto a = static_cast<std::size_t>(pairs[p].first);
    const auto b = static_cast<std::size_t>(pairs[p].second);
    ledger.decided();
    bool proven = false;
    if (configurations_usable && p < distance_from.relative.size() &&
        p < distance_to.relative.size() && p < bounds.relative.size()) {
      Rational bound = bounds.relative[p];
      if (a < hull_bounds.size() && b < hull_bounds.size() && hull_bounds[a] && hull_bounds[b] &&
          *hull_bounds[a] + *hull_bounds[b] < bound) {
        bound = *hull_bounds[a] + *hull_bounds[b];
      }
      const Rational& d_from = distance_from.relative[p];
      const Rational& d_to = distance_to.relative[p];
      proven = bound < d_from + d_to;
      Rational kept = kept_gap(d_from, d_to, bound);
      // proof: proofs/two-ball-cover.md#revolution-route (either route proves the pair)
      if (p < bounds.revolution.size() && bounds.revolution[p]) {
        const Rational& c_from = distance_from.revolution[p];
        const Rational& c_to = distance_to.revolution[p];
        Rational route = *bounds.revolution[p];
        // M_v only where the other routes leave the pair unproven or short of the tolerance
        // (c > 0: not clamped up to 0). proof: proofs/two-ball-cover.md#revolution-vertex-bound
        const bool needed = !(proven || route < c_from + c_to) ||
                            std::max(kept, kept_gap(c_from, c_to, route)) < exact(header.tolerance);
        if (needed && vertex_bound && c_from > 0 && c_to > 0) {
          if (const std::optional<Rational> vertex = vertex_bound(p)) route = std::min(route, *vertex);
        }
        proven = proven || route < c_from + c_to;
        kept = std::max(kept, kept_gap(c_from, c_to, route));
      }
      hold_gap_to_tolerance(cell, header, p, kept, ledger, facts, where);
    }
    if (proven) continue;
    if (claimed.certified) {
      ledger.fail(pair_where(cell, p, where) + ": the relative motion bound is not below d_k + d_k+1");
    }
    facts.all_transitions_certified = false;
  }
}

}  // namespace grpvss::certify
