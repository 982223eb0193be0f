#pragma once
/// \file
/// \brief Centroid-sphere pre-judgement (thesis Eq. 4-19..4-22) in two modes.
///
/// Thesis mode reproduces the 1988 formulas in plain double arithmetic:
/// \f[ P_c = \tfrac{1}{n}\sum_i P_i,\quad D = \max_i \lvert P_c - P_i\rvert,\quad
///     DIS = \lvert P_{c,i} - P_{c,j}\rvert,\quad \text{cull iff } DIS \ge D_i + D_j + \Delta. \f]
/// Certified mode uses the same centre but rounds every radius UP and the centre distance
/// DOWN, so a cull is a proof that the hulls are at least `sphere_gap` apart:
/// \f$\mathrm{dist}(\mathrm{conv}\,H_i, \mathrm{conv}\,H_j) \ge DIS - r_i - r_j\f$ because
/// each hull lies in its ball. proof: proofs/fast-path.md#centroid-sphere-cull
///
/// Every record carries all numbers a checker needs to re-verify the cull from the points.

#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// \brief Thesis Eq. 4-19 and 4-20: centroid (vertex mean) and largest centroid-vertex distance.
struct CentroidSphere {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< \f$P_c\f$ (Eq. 4-19)
  double radius = 0.0;                                 ///< \f$D\f$ (Eq. 4-20)
};

/// \brief Thesis-mode sphere of \p points (plain double, round to nearest).
/// \throws std::invalid_argument if \p points is empty.
CentroidSphere thesis_centroid_sphere(const std::vector<Eigen::Vector3d>& points);

/// \brief The numbers of one thesis-mode pre-judgement (Eq. 4-21, 4-22).
struct ThesisCullRecord {
  CentroidSphere sphere_i;
  CentroidSphere sphere_j;
  double centroid_distance = 0.0;  ///< \f$DIS_{ij}\f$ (Eq. 4-21)
  double tolerance = 0.0;          ///< \f$\Delta\f$
  bool culled = false;             ///< \f$DIS_{ij} \ge D_i + D_j + \Delta\f$ (Eq. 4-22)
};

/// \brief Thesis Eq. 4-21/4-22 on two precomputed spheres. NOT a certified decision.
ThesisCullRecord thesis_prejudge(const CentroidSphere& i, const CentroidSphere& j,
                                 double tolerance);

/// \brief A ball proven to contain every point: \f$\lvert p - c\rvert \le r\f$ holds exactly
/// for the double centre \p center and double radius \p radius_upper.
struct CertifiedSphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius_upper = 0.0;
};

/// \brief Certified sphere: centre = vertex mean (any centre is sound), radius rounded up.
/// \throws std::invalid_argument if \p points is empty.
CertifiedSphere certified_sphere(const std::vector<Eigen::Vector3d>& points);

/// \brief The numbers of one certified centroid cull, enough to re-verify it exactly.
struct CertifiedCullRecord {
  CertifiedSphere sphere_i;
  CertifiedSphere sphere_j;
  double center_distance_lower = 0.0;  ///< \f$\le \lvert c_i - c_j\rvert\f$
  /// \f$\le \lvert c_i - c_j\rvert - r_i - r_j\f$ (may be negative); a proven lower bound
  /// of the hull distance when positive.
  double sphere_gap_lower = 0.0;
  double required_gap = 0.0;  ///< what the caller asked to prove
  bool culled = false;        ///< sphere_gap_lower >= required_gap (and > 0 if required is 0)
};

/// \brief Certified cull: culled proves \f$\mathrm{dist}(H_i, H_j) \ge\f$ sphere_gap_lower
/// \f$\ge\f$ \p required_gap (strictly positive, so the hulls are separated).
CertifiedCullRecord certified_sphere_cull(const CertifiedSphere& i, const CertifiedSphere& j,
                                          double required_gap);

}  // namespace grpvss::geometry
