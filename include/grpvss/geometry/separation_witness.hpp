#pragma once
/// \file
/// \brief Separating-plane witnesses: evidence that two convex point sets are apart by at least
/// a stated distance, which a checker re-verifies exactly from the points alone.
/// proof: proofs/interference.md#separation-witness

#include <optional>
#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// \brief A slab between conv(a) and conv(b):
/// \f$\max_a n\cdot a \le \mathrm{offset\_a} \le \mathrm{offset\_b} \le \min_b n\cdot b\f$.
/// Any point of a and any point of b are then at least
/// \f$(\mathrm{offset\_b} - \mathrm{offset\_a})/|n|\f$ apart. n need not be unit.
struct SeparationWitness {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double offset_a = 0.0;
  double offset_b = 0.0;
};

/// \brief The witness's distance lower bound \f$(\mathrm{offset\_b} - \mathrm{offset\_a})/|n|\f$,
/// rounded DOWN: the returned value d satisfies
/// \f$(\mathrm{offset\_b} - \mathrm{offset\_a}) \ge d\,|n|\f$ exactly (checked exactly).
/// Returns 0 if offset_b - offset_a <= 0 (no positive bound); throws std::invalid_argument for a
/// zero or non-finite normal.
double certified_lower_bound(const SeparationWitness& witness);

/// \brief Exact re-check: every a satisfies n.a <= offset_a, every b satisfies n.b >= offset_b,
/// n != 0, offset_a <= offset_b, all values finite, and
/// \f$\mathrm{offset\_b} - \mathrm{offset\_a} \ge \mathrm{claimed\_lower\_bound}\cdot|n|\f$
/// (squared, exact). A tampered witness (plane moved into either set, bound increased beyond
/// what the slab proves) is rejected.
bool check_witness_exactly(const std::vector<Eigen::Vector3d>& a,
                           const std::vector<Eigen::Vector3d>& b,
                           const SeparationWitness& witness, double claimed_lower_bound);

/// \brief A witness for a separated pair (nullopt if conv(a) and conv(b) touch or overlap).
///
/// Direction: the exact closest-point direction (CGAL Polytope_distance_d, exact arithmetic)
/// rounded to double; offsets are then the exact support values rounded outward. If rounding
/// leaves no gap (distance ~1e-300), the best exact separating axis of the SAT is tried.
/// The witness always satisfies check_witness_exactly(a, b, w, certified_lower_bound(w)).
/// Its certified_lower_bound is close to the true distance (relative loss ~1e-15) when the
/// closest-point direction succeeded.
/// \throws DegenerateHullError if either set does not span 3-D.
std::optional<SeparationWitness> exact_separation_witness(const std::vector<Eigen::Vector3d>& a,
                                                          const std::vector<Eigen::Vector3d>& b);

/// \brief A double d with d <= dist(conv(a), conv(b))^2 (exact squared distance from
/// Polytope_distance_d, rounded down). 0 for touching or overlapping sets. Never exceeds the
/// true squared distance.
double exact_distance_squared_lower(const std::vector<Eigen::Vector3d>& a,
                                    const std::vector<Eigen::Vector3d>& b);

}  // namespace grpvss::geometry
