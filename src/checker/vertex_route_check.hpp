#pragma once
// The revolution route weighed vertex by vertex, decided exactly (proofs/two-ball-cover.md#revolution-vertex-bound):
// M_v = max(0, max_v (V_b D(v) - min(e_k(v), e_k+1(v)))) from the certificate's witnesses at both
// ends of a transition and the checker's own placed vertices. The maximum is found by branch and
// bound over the hull's vertex clusters (geometry::cluster_vertices), each cluster's radius
// verified exactly; D(v), the vertex's distance from its own link's joint axis, is evaluated
// once per hull (it is the same at every configuration).

#include <optional>
#include <vector>

#include "checked_cell.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/geometry/vertex_clusters.hpp"

namespace grpvss::certify {

class VertexRouteCheck {
 public:
  VertexRouteCheck(const CheckedCell& cell, const Certificate& header);

  /// Whether self pair p may take the vertex bound: hull a has a verified solid of revolution and
  /// the only joint left between them, b's own, is revolute (link b = link a + 2).
  bool applies(std::size_t p) const;

  /// M_v of self pair p over one transition: `X_WL_from` / `X_WL_to` are hull b's link poses and
  /// `placed_from` / `placed_to` its raw vertices as the checker placed them at the two ends,
  /// `increment` the exact variation of b's joint. nullopt when a witness is unusable (not separated, non-finite, or a vertex on its
  /// wrong side) or the hull's clusters did not verify.
  std::optional<Rational> bound(std::size_t p, const SelfPairRecord& from, const SelfPairRecord& to,
                                const Eigen::Isometry3d& X_WL_from, const Eigen::Isometry3d& X_WL_to,
                                const std::vector<Eigen::Vector3d>& placed_from,
                                const std::vector<Eigen::Vector3d>& placed_to, const Rational& increment);

 private:
  /// Per hull: its clusters (radii verified exactly) and each vertex's D, built on first use.
  struct HullTerms {
    bool built = false;
    bool usable = false;
    std::vector<geometry::VertexCluster> clusters;
    std::vector<Rational> axis_distance;          ///< D(v) per vertex
    std::vector<Rational> cluster_axis_distance;  ///< the largest D(v) per cluster
  };
  const HullTerms& terms(int hull);

  const CheckedCell* cell_;
  const Certificate* header_;
  std::vector<HullTerms> hull_terms_;
};

}  // namespace grpvss::certify
