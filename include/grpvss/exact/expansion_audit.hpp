#pragma once
/// \file
/// \brief Audit of tolerance expansions: for every link hull of a robot, does an expansion
/// contain every point within the tolerance D of the hull (decided exactly), how far does it
/// miss, and how much does it over-inflate? Compares the thesis's floating-point expansion
/// (Eq. 4-1..4-12, in single and double precision) with the exact cube and rhombicuboctahedron
/// Minkowski offsets. Findings for the IBM 7545: docs/expansion-audit.md.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::geometry {

/// \brief Volume of the ideal ball sum \f$H \oplus B(0,r)\f$ by Steiner's formula for a convex
/// polytope:
/// \f[ V + A\,r + \frac{r^2}{2}\sum_{e} \ell_e\,\psi_e + \frac{4}{3}\pi r^3, \f]
/// A the surface area, \f$\ell_e\f$ the edge lengths, \f$\psi_e\f$ the angle between the
/// outward normals of the two faces at edge e. Evaluated in double from the polytope's rounded
/// normals: a diagnostic (relative error ~1e-12), never a decision.
double ball_sum_volume(const ConvexPolytope& hull, double radius);

/// \brief Which expansion a row describes.
enum class ExpansionMethod {
  kThesisSingle,         ///< Eq. 4-1..4-12 in float (the thesis's "short floating")
  kThesisDouble,         ///< Eq. 4-1..4-12 in double
  kCube,                 ///< exact Minkowski offset with the cube of half-side D
  kRhombicuboctahedron,  ///< exact Minkowski offset with the tight rhombicuboctahedron
};

/// Stable name used in the text table and JSON: "thesis-single", "thesis-double", "cube",
/// "rhombicuboctahedron".
const char* to_string(ExpansionMethod method);

/// \brief One expansion of one hull, measured.
struct ExpansionMeasure {
  ExpansionMethod method = ExpansionMethod::kCube;
  /// False when the method does not apply (thesis expansion of a hull without 16 points);
  /// all other fields are then meaningless.
  bool applicable = true;
  /// Exact verdict: the expansion contains every point within D of the hull.
  bool contains_ball_sum = false;
  /// \f$\max_{faces}(\max_h n\cdot h + D|n| - c)/|n|\f$ over the expansion's faces (double,
  /// after the exact decision): > 0 is how far the worst point within D of the hull pokes out
  /// of the expansion, <= 0 the smallest margin.
  double worst_protrusion = 0.0;
  /// The point within D of the hull that realizes worst_protrusion (link frame).
  Eigen::Vector3d worst_point = Eigen::Vector3d::Zero();
  /// Vertices of the exact convex hull of the expansion's points.
  int vertex_count = 0;
  /// Exact volume of the expansion (rounded once).
  double volume = 0.0;
  /// volume / ball_sum_volume(hull, D): >= 1 for a containing expansion.
  double over_inflation = 0.0;
  /// Thesis only: largest midpoint gap \f$\|P_1^*-P_2^*\|\f$ (Eq. 4-10/4-11), in the method's
  /// precision.
  std::optional<double> max_midpoint_gap;
  /// Thesis only: vertices where the two offset lines were exactly parallel (DENO == 0).
  int parallel_pairs = 0;
  /// Thesis only: Eq. 4-2 sign decisions taken with the link origin on the cap plane.
  int origin_on_cap_plane = 0;
};

/// \brief All expansions of one link hull.
struct HullExpansionAudit {
  int link = 0;         ///< link index (0 = base)
  int hull = 0;         ///< hull index within the link (0-based)
  int source_line = 0;  ///< line of the hull's first point in the robot file
  int point_count = 0;  ///< points given in the file
  int vertex_count = 0; ///< vertices of the exact hull of those points
  double volume = 0.0;  ///< exact volume of the hull (rounded once)
  double ball_sum_volume = 0.0;  ///< ball_sum_volume(hull, D)
  /// In ExpansionMethod order: thesis-single, thesis-double, cube, rhombicuboctahedron.
  std::vector<ExpansionMeasure> expansions;
};

struct ExpansionAudit {
  double tolerance = 0.0;
  std::vector<HullExpansionAudit> hulls;  ///< link by link, hull by hull
};

/// \brief Audit every link hull of \p robot at tolerance \p tolerance (the thesis's Delta).
/// \throws std::invalid_argument unless tolerance is finite and > 0;
///         DegenerateHullError if a hull does not span 3-D.
ExpansionAudit audit_expansions(const RobotModel& robot, double tolerance);

}  // namespace grpvss::geometry
