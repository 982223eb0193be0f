#pragma once
// How much a probe must prove of each term: the step march needs every hull's closest
// witnesses (its radii set the step); a configuration's verdict needs any proven slab.

namespace grpvss::certify {

enum class ProbeNeed {
  /// Each hull's radius and each self pair's distance from their closest witnesses (up to the
  /// probe's documented shortcuts): what the step rule needs. The default.
  kClearance,
  /// Only the configuration's verdict: every term is settled by the first slab proven with a
  /// positive gap (ball slab, kept normal, template query, full query, in that order). Every
  /// radius and distance is still a certified lower bound, only farther below the closest.
  /// proof: proofs/configuration-check.md#lemma-configuration-verdict
  kVerdict,
};

}  // namespace grpvss::certify
