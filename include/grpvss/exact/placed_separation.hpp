#pragma once
/// \file
/// \brief The certified separation of two placed link-frame hulls without placing them: the
/// same witness certify_separation() proves over the placed points, from a climb on each
/// template and a bound on the placement's rounding. proof: proofs/fast-path.md#placed-separation

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/certified_query.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/placed_hull.hpp"

namespace grpvss::geometry {

/// \brief Proves that the plane family with normal \p normal_AB separates the placed points
/// \f$\mathrm{fl}(\hat X_a v_i)\f$ of \p a (below) from those of \p b (above), as
/// certify_separation() over those points would, but visiting only the vertices around each
/// template's support vertex. nullopt when the rounded bounds leave no gap or a support
/// vertex cannot be proven maximal (a rounding tie); the caller then places the points.
/// \param a_climb_start, b_climb_start in, where each climb starts; out, where it ended.
std::optional<CertifiedSeparation> certify_placed_separation(const PlacedHull& a, int& a_climb_start,
                                                             const PlacedHull& b, int& b_climb_start,
                                                             const Eigen::Vector3d& normal_AB);

/// \brief The same with B a set of world points (an obstacle), scanned as
/// certify_separation() scans it.
std::optional<CertifiedSeparation> certify_placed_separation(const PlacedHull& a, int& a_climb_start,
                                                             const std::vector<Eigen::Vector3d>& b,
                                                             const Eigen::Vector3d& normal_AB);

/// \brief The filter of certified_pair_query() on two placed hulls: GJK on the templates
/// (gjk.hpp's PlacedHull overload) proposes, certify_placed_separation() proves. A result only
/// when the pair is proven separated; nullopt when the filter proves nothing (overlap, near
/// contact, a rounding tie): the caller places the points and asks certified_pair_query().
/// \param warm_start_direction, a_climb_hint, b_climb_hint as for certified_pair_query().
/// \param simplex_hint optional: the pair's last GJK simplex, in and out (gjk.hpp).
std::optional<CertifiedPairResult> certified_placed_separation_query(
    const PlacedHull& a, const PlacedHull& b, const Eigen::Vector3d* warm_start_direction,
    int* a_climb_hint, int* b_climb_hint, GjkSimplexHint* simplex_hint = nullptr);

/// \brief The same with B a non-empty set of world points (an obstacle).
/// \throws std::invalid_argument if b is empty.
std::optional<CertifiedPairResult> certified_placed_separation_query(
    const PlacedHull& a, const std::vector<Eigen::Vector3d>& b,
    const Eigen::Vector3d* warm_start_direction, int* a_climb_hint,
    GjkSimplexHint* simplex_hint = nullptr);

}  // namespace grpvss::geometry
