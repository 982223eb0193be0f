#pragma once
/// \file
/// \brief A convex polytope built EXACTLY from a point set (the hull of the points).
///
/// The hull's combinatorics are decided with exact predicates on the input doubles (CGAL
/// `convex_hull_3`, exact-predicates kernel), so the thesis's hand-made 16-point hulls never
/// confuse it: points in the middle of an edge or face (robot.txt link 0's -5.125 / -5.625
/// side points) are dropped, and a point group that is not exactly planar becomes several
/// exactly planar faces. Vertices are the input doubles, bit for bit; no coordinate is ever
/// constructed. No CGAL type appears here.

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// \brief Thrown when a point set does not span 3-D: fewer than 4 points, or all points
/// coincident, collinear or coplanar (decided exactly). Also thrown for non-finite coordinates.
class DegenerateHullError : public std::invalid_argument {
 public:
  explicit DegenerateHullError(const std::string& message) : std::invalid_argument(message) {}
};

/// \brief A 3-D convex polytope with exact topology and double vertices.
///
/// Invariants (established by from_points(), which is the only way to build one):
/// - `vertices()` are exactly the extreme points of the input (copied bit for bit);
///   `input_index(i)` is the position of vertex i in the input vector (first occurrence).
/// - `faces()` are vertex-index loops, counter-clockwise seen from outside (outward by the
///   right-hand rule); all vertices of a face are EXACTLY coplanar, coplanar adjacent
///   triangles are merged into one polygon, and no three consecutive loop vertices are
///   collinear (exactly).
/// - `edges()` are index pairs {u, v} with u < v; `edge_faces()[e]` = {the face whose loop
///   contains u->v, the face whose loop contains v->u}. Each edge borders exactly two faces
///   with different planes.
/// - `face_normals()` / `face_offsets()` are unit outward normals n and offsets c (n.x <= c
///   for the face's own vertices, evaluated in double) for display and floating-point
///   filtering ONLY: they are rounded. Exact decisions recompute planes from the vertices.
class ConvexPolytope {
 public:
  /// \brief Exact convex hull of \p points.
  /// \throws DegenerateHullError if the points do not span 3-D (fewer than 4, coincident,
  ///         collinear or coplanar — decided exactly) or contain NaN/inf.
  static ConvexPolytope from_points(const std::vector<Eigen::Vector3d>& points);

  /// \brief Exact convex hull of \p points where `points[reference.input_indices()[j]]` is
  /// a nearby image of `reference.vertices()[j]` (e.g. a link hull placed by floating-point
  /// forward kinematics): the reference's faces, triangulated, are tried first and accepted
  /// only after an exact check that they bound conv(points) (local convexity at every edge,
  /// a centre below every triangle, one ray meeting one triangle;
  /// proof: proofs/placed-hull.md#lemma-placed-hull), otherwise from_points(points).
  /// Either way the result is the same polytope as from_points(points): same vertices in
  /// the same order, same faces up to their order and loop starts.
  static ConvexPolytope from_points_like(const std::vector<Eigen::Vector3d>& points,
                                         const ConvexPolytope& reference);

  /// \brief The template step of from_points_like() alone: the reference's faces, with
  /// reflex edges flipped, if the exact check proves they bound conv(points); nullopt when
  /// it does not (the caller then needs from_points()). Never returns a wrong hull.
  /// proof: proofs/placed-hull.md#lemma-placed-hull
  static std::optional<ConvexPolytope> from_template(const std::vector<Eigen::Vector3d>& points,
                                                     const ConvexPolytope& reference);

  /// Hull vertices, bit-identical copies of input points.
  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  /// Index in the input vector of each hull vertex.
  const std::vector<int>& input_indices() const { return input_indices_; }
  /// Face loops (indices into vertices()), CCW seen from outside.
  const std::vector<std::vector<int>>& faces() const { return faces_; }
  /// Edges {u, v}, u < v (indices into vertices()).
  const std::vector<std::array<int, 2>>& edges() const { return edges_; }
  /// For each edge the two incident faces: [0] has u->v on its loop, [1] has v->u.
  const std::vector<std::array<int, 2>>& edge_faces() const { return edge_faces_; }
  /// Unit outward face normals, rounded (display/filtering only).
  const std::vector<Eigen::Vector3d>& face_normals() const {
    ensure_measures();
    return face_normals_;
  }
  /// Face offsets c = max over the face's vertices of n.v in double (display/filtering).
  const std::vector<double>& face_offsets() const {
    ensure_measures();
    return face_offsets_;
  }

  /// \brief Volume, computed EXACTLY (sum of signed tetrahedra over the exact faces, in
  /// exact arithmetic), converted to double and divided by 6 at the end (relative error
  /// below 2^-51: two roundings).
  double volume() const {
    ensure_measures();
    return volume_;
  }

 private:
  friend struct ConvexPolytopeBuilder;
  ConvexPolytope() = default;

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<int> input_indices_;
  std::vector<std::vector<int>> faces_;
  std::vector<std::array<int, 2>> edges_;
  std::vector<std::array<int, 2>> edge_faces_;
  // Display planes and volume: computed by from_points(), on first use for
  // from_points_like() (the verifier's placed hulls never need them). A lazily filled cache:
  // share between threads only polytopes from from_points() (a RobotCell's; docs/batch.md).
  void ensure_measures() const {
    if (!measures_ready_) compute_measures();
  }
  void compute_measures() const;
  mutable bool measures_ready_ = false;
  mutable std::vector<Eigen::Vector3d> face_normals_;
  mutable std::vector<double> face_offsets_;
  mutable double volume_ = 0.0;
};

}  // namespace grpvss::geometry
