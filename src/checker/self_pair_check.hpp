#pragma once
// Self-collision in the certificate: at every step each self pair's separating slab is decided
// exactly on the two raw hulls as the checker places them, giving a distance lower bound d;
// across every transition M_a + M_b < d_k + d_{k+1} is decided exactly, and with the claim
// `motion` the gap kept along the motion against the tolerance.
// proof: proofs/two-ball-cover.md#lemma-relative-motion, proofs/cell-geometry.md#lemma-geometry-error

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "check_ledger.hpp"
#include "checked_cell.hpp"
#include "claim_facts.hpp"
#include "grpvss/evidence/certificate.hpp"

namespace grpvss::certify {

/// Every self pair's exactly verified distance lower bounds at one step (0 where nothing is
/// proven), in CheckedCell::self_pairs() order.
struct SelfPairDistances {
  std::vector<Rational> relative;    ///< d: between the two hulls
  std::vector<Rational> revolution;  ///< from hull a's solid of revolution to hull b (the revolution route)
};

/// Every self pair's exact motion bounds over one transition, by route, in
/// CheckedCell::self_pairs() order (TransitionCheck).
struct SelfPairBounds {
  /// M_b|a: hull b in link a's frame (proofs/two-ball-cover.md#relative-frame)
  std::vector<Rational> relative;
  /// M_b|a+1 for a pair whose hull a has a verified solid of revolution, else nullopt
  /// (proofs/two-ball-cover.md#revolution-route)
  std::vector<std::optional<Rational>> revolution;
};

/// The revolution route weighed vertex by vertex, M_v of pair p, decided on demand (it costs a
/// pass over hull b's vertices); nullopt where the pair has none. It holds only with both ends'
/// route distances c > 0 unclamped (proofs/two-ball-cover.md#revolution-vertex-bound).
using VertexRouteBound = std::function<std::optional<Rational>(std::size_t pair)>;

/// \brief The self pairs' verified distances at `step`. `placed_raw[i]`: hull i's raw
/// vertices placed at the step (empty when the step check could not place it); `X_WL`: the
/// checker's link poses at the step (the revolution route's cylinder is placed by them).
SelfPairDistances check_self_pair_evidence(
    const CheckedCell& cell, const Certificate& header, const StepCertificate& step,
    const std::vector<std::vector<Eigen::Vector3d>>& placed_raw,
    const std::vector<Eigen::Isometry3d>& X_WL, CheckLedger& ledger, const std::string& where);

/// \brief Decides min(M_a + M_b, M_b|a) < d_k + d_{k+1}, or for a pair with a revolution
/// route min(M_b|a+1, M_v) < c_k + c_{k+1} (`bounds`, `vertex_bound` for M_v, c the solid's
/// distances), for every self pair, M_a and M_b the
/// hulls' verified motion bounds (`hull_bounds`, nullopt where none is proven), M_b|a the exact
/// joint-sum bound of hull b over joints a+1..b (its motion in link a's frame). A failing pair
/// fails the ledger when the transition claims to be certified; either way it makes it
/// uncertified in `facts`. The pair's gap along the motion,
/// g = max((d_k + d_{k+1} - M)/2, max(d_k, d_{k+1}) - M), is held to the tolerance: g < Delta
/// sets facts.any_tolerance_shortfall, and fails the ledger when `header` claims CLEAR with
/// the claim `motion`. proof: proofs/two-ball-cover.md#corollary-self-tolerance-along-motion
void check_self_pair_transition(const CheckedCell& cell, const Certificate& header,
                                const StepCertificate& from, const StepCertificate& to,
                                const TransitionRecord& claimed,
                                const std::vector<std::optional<Rational>>& hull_bounds,
                                const SelfPairBounds& bounds, const VertexRouteBound& vertex_bound,
                                const SelfPairDistances& distance_from,
                                const SelfPairDistances& distance_to, CheckLedger& ledger,
                                ClaimFacts& facts, const std::string& where);

}  // namespace grpvss::certify
