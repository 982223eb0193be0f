/// \file
/// \brief CGAL translation unit 2 of 2: exact contact classification (filtered SAT),
/// exact interference points, separation witnesses and exact distances.
///
/// Filtering discipline (cgal-notes.md): interval arithmetic (Interval_nt<false>) runs only
/// inside a Protect_FPU_rounding<true> scope; every exact fallback (Gmpzf, Mpzf, Gmpq)
/// runs after that scope has restored round-to-nearest.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/FPU.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/exact_contact.hpp"
#include "exact_rounding.hpp"
#include "grpvss/geometry/separation_witness.hpp"

namespace grpvss::geometry {

namespace {

using IV = CGAL::Interval_nt<false>;  // needs a Protect_FPU_rounding<true> scope
using Exact = CGAL::Gmpzf;            // exact +, -, * of doubles
using Rational = CGAL::Gmpq;          // exact division (interference points only)
using IV3 = std::array<IV, 3>;
using Exact3 = std::array<Exact, 3>;
using Rational3 = std::array<Rational, 3>;

// ---- small exact / interval vector helpers ---------------------------------------------------

template <class T>
std::array<T, 3> cross(const std::array<T, 3>& u, const std::array<T, 3>& w) {
  return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}
template <class T>
T dot(const std::array<T, 3>& u, const std::array<T, 3>& w) {
  return u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
}
template <class T>
std::array<T, 3> lift(const Eigen::Vector3d& v) {
  return {T(v.x()), T(v.y()), T(v.z())};
}
template <class T>
std::array<T, 3> minus(const std::array<T, 3>& u, const std::array<T, 3>& w) {
  return {u[0] - w[0], u[1] - w[1], u[2] - w[2]};
}
template <class T>
std::array<T, 3> diff(const Eigen::Vector3d& q, const Eigen::Vector3d& p) {
  return minus(lift<T>(q), lift<T>(p));
}
template <class T>
bool is_zero3(const std::array<T, 3>& u) {
  return CGAL::is_zero(u[0]) && CGAL::is_zero(u[1]) && CGAL::is_zero(u[2]);
}

enum class Certain { kNegative, kZero, kPositive, kUnknown };
Certain sign_of(const IV& x) {
  if (x.inf() > 0) return Certain::kPositive;
  if (x.sup() < 0) return Certain::kNegative;
  if (x.inf() == 0 && x.sup() == 0) return Certain::kZero;
  return Certain::kUnknown;
}

// ---- exact hull data --------------------------------------------------------------------------

/// A ConvexPolytope plus the (outward, non-normalized) face normals as exact products of
/// vertex differences: n_f = (v1 - v0) x (v2 - v0) for the face's first three loop vertices.
struct Hull {
  explicit Hull(const ConvexPolytope& p) : poly(p) {}
  const ConvexPolytope& poly;
  const Eigen::Vector3d& vertex(int f, int k) const {
    return poly.vertices()[poly.faces()[f][k]];
  }
  template <class T>
  std::array<T, 3> face_normal(int f) const {
    return cross(diff<T>(vertex(f, 1), vertex(f, 0)), diff<T>(vertex(f, 2), vertex(f, 0)));
  }
  template <class T>
  std::array<T, 3> edge_direction(int e) const {
    const auto& ed = poly.edges()[e];
    return diff<T>(poly.vertices()[ed[1]], poly.vertices()[ed[0]]);
  }
};

/// Candidate separating axis: a face normal of A, of B, or edge(A) x edge(B).
struct Axis {
  enum Kind { kFaceA, kFaceB, kEdges } kind;
  int i;
  int j;
};

template <class T>
std::array<T, 3> axis_vector(const Axis& axis, const Hull& A, const Hull& B) {
  switch (axis.kind) {
    case Axis::kFaceA: return A.face_normal<T>(axis.i);
    case Axis::kFaceB: return B.face_normal<T>(axis.i);
    case Axis::kEdges: return cross(A.edge_direction<T>(axis.i), B.edge_direction<T>(axis.j));
  }
  throw std::logic_error("bad axis kind");
}

enum class AxisVerdict { kSeparates, kTouches, kOverlaps, kUnknown };

/// Interval projections; must run under Protect_FPU_rounding<true>.
AxisVerdict interval_verdict(const IV3& n, const Hull& A, const Hull& B) {
  auto range = [&n](const std::vector<Eigen::Vector3d>& pts, double& lo_min, double& hi_min,
                    double& lo_max, double& hi_max) {
    lo_min = hi_min = lo_max = hi_max = 0.0;
    bool first = true;
    for (const auto& p : pts) {
      const IV d = dot(n, lift<IV>(p));
      if (first) {
        lo_min = lo_max = d.inf();
        hi_min = hi_max = d.sup();
        first = false;
      } else {
        lo_min = std::min(lo_min, d.inf());
        hi_min = std::min(hi_min, d.sup());
        lo_max = std::max(lo_max, d.inf());
        hi_max = std::max(hi_max, d.sup());
      }
    }
  };
  double a_lo_min, a_hi_min, a_lo_max, a_hi_max, b_lo_min, b_hi_min, b_lo_max, b_hi_max;
  range(A.poly.vertices(), a_lo_min, a_hi_min, a_lo_max, a_hi_max);
  range(B.poly.vertices(), b_lo_min, b_hi_min, b_lo_max, b_hi_max);
  // max A in [a_lo_max, a_hi_max], min B in [b_lo_min, b_hi_min], etc.
  if (a_hi_max < b_lo_min || b_hi_max < a_lo_min) return AxisVerdict::kSeparates;
  if (a_lo_max > b_hi_min && b_lo_max > a_hi_min) return AxisVerdict::kOverlaps;
  return AxisVerdict::kUnknown;
}

/// Exact projections (round-to-nearest mode; Gmpzf is exact anyway).
AxisVerdict exact_verdict(const Exact3& n, const Hull& A, const Hull& B) {
  if (is_zero3(n)) return AxisVerdict::kOverlaps;  // no axis: decides nothing
  auto range = [&n](const std::vector<Eigen::Vector3d>& pts, Exact& lo, Exact& hi) {
    lo = hi = dot(n, lift<Exact>(pts.front()));
    for (std::size_t i = 1; i < pts.size(); ++i) {
      const Exact d = dot(n, lift<Exact>(pts[i]));
      if (d < lo) lo = d;
      if (d > hi) hi = d;
    }
  };
  Exact a_min, a_max, b_min, b_max;
  range(A.poly.vertices(), a_min, a_max);
  range(B.poly.vertices(), b_min, b_max);
  if (a_max < b_min || b_max < a_min) return AxisVerdict::kSeparates;
  if (a_max == b_min || b_max == a_min) return AxisVerdict::kTouches;
  return AxisVerdict::kOverlaps;
}

/// Gauss-map test (Gregorius, "The Separating Axis Test between Convex Polyhedra", GDC 2013):
/// do the arcs of edge eA (between A's face normals a, b) and of edge eB (between B's NEGATED
/// face normals c, d) cross in their interiors? Only then is eA x eB a facet normal of A - B.
/// Returns false only when intervals PROVE no crossing (keeping extra axes is always sound).
/// Must run under Protect_FPU_rounding<true>.
bool may_be_minkowski_face(const IV3& a, const IV3& b, const IV3& c, const IV3& d) {
  const IV3 bxa = cross(b, a);
  const IV3 dxc = cross(d, c);
  const Certain cba = sign_of(dot(c, bxa));
  const Certain dba = sign_of(dot(d, bxa));
  const Certain adc = sign_of(dot(a, dxc));
  const Certain bdc = sign_of(dot(b, dxc));
  const auto u = Certain::kUnknown;
  if (cba == u || dba == u || adc == u || bdc == u) return true;
  const auto s = [](Certain x) { return x == Certain::kPositive ? 1 : x == Certain::kNegative ? -1 : 0; };
  return s(cba) * s(dba) < 0 && s(adc) * s(bdc) < 0 && s(cba) * s(bdc) > 0;
}

/// Face normals of A, of B, then the edge pairs that may be facets of A - B.
/// proof: proofs/interference.md#exact-sat (facet normals of A - B are among these).
std::vector<Axis> candidate_axes(const Hull& A, const Hull& B) {
  std::vector<Axis> axes;
  const int fa = static_cast<int>(A.poly.faces().size());
  const int fb = static_cast<int>(B.poly.faces().size());
  for (int f = 0; f < fa; ++f) axes.push_back({Axis::kFaceA, f, -1});
  for (int f = 0; f < fb; ++f) axes.push_back({Axis::kFaceB, f, -1});
  CGAL::Protect_FPU_rounding<true> guard;
  std::vector<IV3> na, nb;
  for (int f = 0; f < fa; ++f) na.push_back(A.face_normal<IV>(f));
  for (int f = 0; f < fb; ++f) {
    const IV3 n = B.face_normal<IV>(f);
    nb.push_back({-n[0], -n[1], -n[2]});
  }
  const auto& efa = A.poly.edge_faces();
  const auto& efb = B.poly.edge_faces();
  for (std::size_t i = 0; i < efa.size(); ++i) {
    for (std::size_t j = 0; j < efb.size(); ++j) {
      if (may_be_minkowski_face(na[efa[i][0]], na[efa[i][1]], nb[efb[j][0]], nb[efb[j][1]])) {
        axes.push_back({Axis::kEdges, static_cast<int>(i), static_cast<int>(j)});
      }
    }
  }
  return axes;
}

Contact classify_hulls(const Hull& A, const Hull& B) {
  const std::vector<Axis> axes = candidate_axes(A, B);
  std::vector<Axis> undecided;
  bool separated = false;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    for (const Axis& axis : axes) {
      const AxisVerdict v = interval_verdict(axis_vector<IV>(axis, A, B), A, B);
      if (v == AxisVerdict::kSeparates) {
        separated = true;
        break;
      }
      if (v == AxisVerdict::kUnknown) undecided.push_back(axis);
    }
  }  // round-to-nearest restored before the exact fallback
  if (separated) return Contact::kSeparated;
  bool touching = false;
  for (const Axis& axis : undecided) {
    const AxisVerdict v = exact_verdict(axis_vector<Exact>(axis, A, B), A, B);
    if (v == AxisVerdict::kSeparates) return Contact::kSeparated;
    if (v == AxisVerdict::kTouches) touching = true;
  }
  return touching ? Contact::kTouching : Contact::kOverlapping;
}

/// Exact bounding-box separation (pure double comparisons are exact).
bool boxes_separate(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  Eigen::Vector3d a_min = a.front(), a_max = a.front(), b_min = b.front(), b_max = b.front();
  for (const auto& p : a) {
    a_min = a_min.cwiseMin(p);
    a_max = a_max.cwiseMax(p);
  }
  for (const auto& p : b) {
    b_min = b_min.cwiseMin(p);
    b_max = b_max.cwiseMax(p);
  }
  for (int k = 0; k < 3; ++k) {
    if (a_max[k] < b_min[k] || b_max[k] < a_min[k]) return true;
  }
  return false;
}

/// Exactly: do the points span 3-D? (Cheap: O(n) filtered predicates, no hull.)
bool spans_3d(const std::vector<Eigen::Vector3d>& pts) {
  using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<P> q;
  q.reserve(pts.size());
  for (const auto& p : pts) {
    if (!p.allFinite()) return false;
    q.emplace_back(p.x(), p.y(), p.z());
  }
  const std::size_t n = q.size();
  std::size_t i1 = 1;
  while (i1 < n && q[i1] == q[0]) ++i1;
  if (i1 >= n) return false;
  std::size_t i2 = 1;
  while (i2 < n && CGAL::collinear(q[0], q[i1], q[i2])) ++i2;
  if (i2 >= n) return false;
  std::size_t i3 = 1;
  while (i3 < n && CGAL::orientation(q[0], q[i1], q[i2], q[i3]) == CGAL::COPLANAR) ++i3;
  return i3 < n;
}

void require_points(const std::vector<Eigen::Vector3d>& pts, const char* what) {
  if (pts.empty()) throw std::invalid_argument(std::string(what) + ": empty point set");
  for (const auto& p : pts) {
    if (!p.allFinite()) throw std::invalid_argument(std::string(what) + ": non-finite point");
  }
}

// ---- rounding helpers ------------------------------------------------------------------------

/// Next candidate below r > 0: one ulp for the first steps, then geometric, so a badly
/// rounded start (or an overflowed one) still reaches a valid value quickly.
double step_down(double r, int iteration) {
  const double ulp_step = std::nextafter(r, 0.0);
  return iteration < 8 ? ulp_step : std::min(ulp_step, r * (1.0 - 0x1p-20));
}

double round_up(const Exact& x) {
  double hi = CGAL::to_interval(x).second;
  while (Exact(hi) < x) hi = std::nextafter(hi, std::numeric_limits<double>::infinity());
  return hi;
}
double round_down(const Exact& x) {
  double lo = CGAL::to_interval(x).first;
  while (Exact(lo) > x) lo = std::nextafter(lo, -std::numeric_limits<double>::infinity());
  return lo;
}

}  // namespace

// ---- classification ----------------------------------------------------------------------------

const char* to_string(Contact contact) {
  switch (contact) {
    case Contact::kSeparated: return "separated";
    case Contact::kTouching: return "touching";
    case Contact::kOverlapping: return "overlapping";
  }
  return "?";
}

const char* to_string(InterferenceKind kind) {
  switch (kind) {
    case InterferenceKind::kEdgeOfAOnFaceOfB: return "edge-of-A/face-of-B";
    case InterferenceKind::kEdgeOfBOnFaceOfA: return "edge-of-B/face-of-A";
    case InterferenceKind::kVertexOfAInB: return "vertex-of-A-in-B";
    case InterferenceKind::kVertexOfBInA: return "vertex-of-B-in-A";
  }
  return "?";
}

Contact classify_exact(const std::vector<Eigen::Vector3d>& a,
                       const std::vector<Eigen::Vector3d>& b) {
  // proof: proofs/interference.md#exact-sat
  // Degenerate input must throw whatever the boxes say; spans_3d is the cheap test, the hull
  // constructor throws the detailed message.
  if (a.empty() || b.empty() || !spans_3d(a) || !spans_3d(b)) {
    ConvexPolytope::from_points(a);
    ConvexPolytope::from_points(b);
    throw std::logic_error("spans_3d and ConvexPolytope::from_points disagree");
  }
  if (boxes_separate(a, b)) return Contact::kSeparated;
  return classify_exact(ConvexPolytope::from_points(a), ConvexPolytope::from_points(b));
}

Contact classify_exact(const ConvexPolytope& a, const ConvexPolytope& b) {
  // proof: proofs/interference.md#exact-sat
  if (boxes_separate(a.vertices(), b.vertices())) return Contact::kSeparated;
  return classify_hulls(Hull(a), Hull(b));
}

// ---- interference points -----------------------------------------------------------------------

namespace {

using Fast = CGAL::Mpzf;  // exact +, -, * of doubles, small values on the stack (no malloc)
using Fast3 = std::array<Fast, 3>;

/// An exact rational point num / den (den > 0), plus its round-to-nearest double image. A
/// crossing rounded by the error-bound filter keeps its segment and face plane instead, and
/// gets num / den only if a duplicate test needs them.
struct ExactPoint {
  Fast3 num;
  Fast den;
  Eigen::Vector3d rounded;
  bool exact_known = true;
  std::array<Eigen::Vector3d, 5> crossing;  // p, q, f0, f1, f2 while !exact_known

  /// X = (s_p q - s_q p) / (s_p - s_q), s_x = ((f1 - f0) x (f2 - f0)) . (x - f0).
  void make_exact() {
    if (exact_known) return;
    const auto& [p_d, q_d, f0, f1, f2] = crossing;
    const Fast3 n = cross(diff<Fast>(f1, f0), diff<Fast>(f2, f0));
    const Fast s_p = dot(n, diff<Fast>(p_d, f0));
    const Fast s_q = dot(n, diff<Fast>(q_d, f0));
    const Fast3 p = lift<Fast>(p_d);
    const Fast3 q = lift<Fast>(q_d);
    for (int k = 0; k < 3; ++k) num[k] = s_p * q[k] - s_q * p[k];
    den = s_p - s_q;
    if (CGAL::sign(den) == CGAL::NEGATIVE) {
      for (auto& c : num) c = -c;
      den = -den;
    }
    exact_known = true;
  }
};

struct PointCollector {
  std::vector<std::pair<ExactPoint, InterferencePoint>> found;

  void add(ExactPoint x, InterferenceKind kind, int first, int second) {
    if (!x.exact_known) {
      // rounded by crossing_rounded_by_error_bound already
    } else if (x.den == Fast(1)) {
      for (int k = 0; k < 3; ++k) x.rounded[k] = CGAL::to_double(x.num[k]);
    } else {
      for (int k = 0; k < 3; ++k) x.rounded[k] = round_quotient_to_nearest(x.num[k], x.den);
    }
    for (auto& [y, ip] : found) {
      // Equal exact points round equally, so only equal roundings need the exact test.
      if (ip.kind != kind || y.rounded != x.rounded) continue;
      x.make_exact();
      y.make_exact();
      bool same = true;
      for (int k = 0; k < 3 && same; ++k) same = x.num[k] * y.den == y.num[k] * x.den;
      if (same) return;
    }
    InterferencePoint ip;
    ip.point = x.rounded;
    ip.kind = kind;
    ip.feature_first = first;
    ip.feature_second = second;
    found.emplace_back(std::move(x), ip);
  }
};

ExactPoint exact_vertex(const Eigen::Vector3d& v) {
  return {lift<Fast>(v), Fast(1), v, true, {}};
}

/// Per face of `faces_of`: the exact sign of n_f . (v - v_0) for every vertex v of
/// `edges_of`, and of the in-face edge tests. Interval arithmetic decides what it can; the
/// exact (Mpzf) values are built only for the undecided cases.
class FaceSides {
 public:
  FaceSides(const Hull& faces_of, const std::vector<Eigen::Vector3d>& points, int face)
      : faces_of_(faces_of), points_(points), face_(face), loop_(faces_of.poly.faces()[face]) {}

  const std::vector<int>& loop() const { return loop_; }
  const Fast3& normal() {
    if (!normal_) normal_ = faces_of_.face_normal<Fast>(face_);
    return *normal_;
  }
  /// Exact n . (p - v_0) for point index i.
  const Fast& side(std::size_t i) {
    // Sized on first use: most faces never need an exact side (intervals decide them).
    if (have_exact_side_.empty()) {
      exact_side_.resize(points_.size());
      have_exact_side_.assign(points_.size(), 0);
    }
    if (!have_exact_side_[i]) {
      exact_side_[i] = dot(normal(), diff<Fast>(points_[i], faces_of_.vertex(face_, 0)));
      have_exact_side_[i] = 1;
    }
    return exact_side_[i];
  }
  /// Exact m_k = n x w_k, w_k the k-th loop edge: x in the face plane is inside the face iff
  /// m_k . (x - v_k) >= 0 for every k.
  const Fast3& edge_normal(std::size_t k) {
    if (edge_normals_.empty()) {
      const auto& fv = faces_of_.poly.vertices();
      for (std::size_t i = 0; i < loop_.size(); ++i) {
        edge_normals_.push_back(
            cross(normal(), diff<Fast>(fv[loop_[(i + 1) % loop_.size()]], fv[loop_[i]])));
      }
    }
    return edge_normals_[k];
  }

 private:
  const Hull& faces_of_;
  const std::vector<Eigen::Vector3d>& points_;
  int face_;
  const std::vector<int>& loop_;
  std::optional<Fast3> normal_;
  std::vector<Fast> exact_side_;
  std::vector<char> have_exact_side_;
  std::vector<Fast3> edge_normals_;
};

int exact_sign(const Fast& x) { return static_cast<int>(CGAL::sign(x)); }
int certain_int(Certain c) { return c == Certain::kPositive ? 1 : c == Certain::kNegative ? -1 : 0; }

/// Edge p + t d (t in [0, 1]) lying in the face's plane: the end points of its part inside
/// the closed face, exactly (t = tn / td with td > 0). Rare, so no filter.
void coplanar_edge_points(FaceSides& face, const Hull& faces_of, const Eigen::Vector3d& p_d,
                          const Eigen::Vector3d& q_d, InterferenceKind kind, int e, int f,
                          PointCollector& out) {
  const auto& fv = faces_of.poly.vertices();
  const Fast3 p = lift<Fast>(p_d);
  const Fast3 d = diff<Fast>(q_d, p_d);
  Fast lo_n(0), lo_d(1), hi_n(1), hi_d(1);
  const auto& loop = face.loop();
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const Fast3& m = face.edge_normal(k);
    const Fast alpha = dot(m, minus(p, lift<Fast>(fv[loop[k]])));
    const Fast beta = dot(m, d);
    // alpha + beta t >= 0
    const int sb = exact_sign(beta);
    if (sb == 0) {
      if (exact_sign(alpha) < 0) return;
    } else if (sb > 0) {  // t >= -alpha / beta
      const Fast tn = -alpha;
      if (tn * lo_d > lo_n * beta) {
        lo_n = tn;
        lo_d = beta;
      }
    } else {  // t <= alpha / -beta
      const Fast td = -beta;
      if (alpha * hi_d < hi_n * td) {
        hi_n = alpha;
        hi_d = td;
      }
    }
    if (lo_n * hi_d > hi_n * lo_d) return;
  }
  for (const auto& [tn, td] : {std::make_pair(lo_n, lo_d), std::make_pair(hi_n, hi_d)}) {
    ExactPoint x;
    for (int k = 0; k < 3; ++k) x.num[k] = p[k] * td + tn * d[k];
    x.den = td;
    out.add(std::move(x), kind, e, f);
  }
}

/// Axis-aligned box of some points (exact double compares).
struct PointBox {
  Eigen::Vector3d lo, hi;
  bool misses(const PointBox& other) const {
    return (hi.array() < other.lo.array()).any() || (other.hi.array() < lo.array()).any();
  }
};

PointBox box_of_all_points(const std::vector<Eigen::Vector3d>& points) {
  PointBox box{points.front(), points.front()};
  for (const Eigen::Vector3d& p : points) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

template <class Indices>
PointBox box_of_points(const std::vector<Eigen::Vector3d>& points, const Indices& indices) {
  PointBox box{points[*indices.begin()], points[*indices.begin()]};
  for (const int i : indices) {
    box.lo = box.lo.cwiseMin(points[i]);
    box.hi = box.hi.cwiseMax(points[i]);
  }
  return box;
}

/// Edges of `edges_of` meeting faces of `faces_of` (closed polygons), exactly.
/// For a crossing with s_p = n.(p - v_0), s_q = n.(q - v_0) of opposite signs the point is
/// X = (s_p q - s_q p) / (s_p - s_q); it is inside the face iff
/// sign(m_k . (N - D v_k)) * sign(D) >= 0 for every loop edge k (N, D its numerator and
/// denominator). Each sign is taken from intervals when they decide it, else computed exactly.
class EdgeFaceScan {
 public:
  EdgeFaceScan(const Hull& edges_of, const Hull& faces_of, InterferenceKind kind,
               PointCollector& out);
  void run();

 private:
  using EpickPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

  /// What one face needs, its exact and interval data built for its first candidate edge only.
  struct FaceScan {
    int f = 0;
    PointBox box;
    EpickPoint f0, f1, f2;
    std::optional<FaceSides> exact;
    IV3 n, v0;
  };
  void collect_near_edges();
  void scan_face(FaceScan& face);
  void edge_meets_face(std::size_t e, FaceScan& face);
  /// Exact plane side of vertex v of edges_of, memoised for the current face.
  int plane_side(const FaceScan& face, int v);
  void prepare_face(FaceScan& face);
  const IV& interval_value(int v, const FaceScan& face);
  /// Interval pass over the loop edges for the crossing of edge (i0, i1): false when the point is
  /// certainly outside the face; `undecided_` holds the loop edges the intervals could not tell.
  bool maybe_inside(FaceScan& face, int i0, int i1, int s0, bool at_end, int end);
  ExactPoint crossing_point(FaceScan& face, int i0, int i1, int s0, bool at_end, int end) const;
  /// The loop edges the intervals left undecided, exactly.
  bool inside_exactly(FaceScan& face, const ExactPoint& x) const;

  const Hull& edges_of_;
  const Hull& faces_of_;
  InterferenceKind kind_;
  PointCollector& out_;
  const std::vector<Eigen::Vector3d>& ev_;
  const std::vector<Eigen::Vector3d>& fv_;
  const std::vector<std::array<int, 2>>& edges_;
  std::vector<EpickPoint> ep_;
  std::vector<PointBox> edge_box_;
  std::vector<std::size_t> near_edges_;
  PointBox edges_of_box_;
  // Per-face caches, sized once.
  std::vector<IV> value_;
  std::vector<char> have_value_;
  std::vector<int> side_;
  std::vector<std::size_t> side_stamp_;
  std::size_t face_stamp_ = 0;
  std::vector<IV3> m_iv_;
  std::vector<IV3> v_iv_;
  std::vector<std::size_t> undecided_;
};

EdgeFaceScan::EdgeFaceScan(const Hull& edges_of, const Hull& faces_of, InterferenceKind kind,
                           PointCollector& out)
    : edges_of_(edges_of),
      faces_of_(faces_of),
      kind_(kind),
      out_(out),
      ev_(edges_of.poly.vertices()),
      fv_(faces_of.poly.vertices()),
      edges_(edges_of.poly.edges()) {}

void EdgeFaceScan::run() {
  collect_near_edges();
  if (near_edges_.empty()) return;
  // Exact plane sides by CGAL's filtered orientation predicate: n.(p - v_0) with
  // n = (v_1 - v_0) x (v_2 - v_0) is det[v_1 - v_0, v_2 - v_0, p - v_0] = orientation(v0, v1, v2, p).
  ep_.reserve(ev_.size());
  for (const auto& v : ev_) ep_.emplace_back(v.x(), v.y(), v.z());
  // Every crossing point lies on an edge, hence in the box of all of edges_of's vertices: a
  // face whose box misses it has none (exact double compares, before any predicate).
  edges_of_box_ = box_of_all_points(ev_);
  value_.resize(ev_.size());
  have_value_.resize(ev_.size());
  side_.resize(ev_.size());
  side_stamp_.assign(ev_.size(), 0);
  for (std::size_t f = 0; f < faces_of_.poly.faces().size(); ++f) {
    FaceScan face;
    face.f = static_cast<int>(f);
    face.box = box_of_points(fv_, faces_of_.poly.faces()[f]);
    if (edges_of_box_.misses(face.box)) continue;
    scan_face(face);
  }
}

// Only edges whose box meets the box of faces_of's vertices can meet any of its faces: the
// face loop visits those alone.
void EdgeFaceScan::collect_near_edges() {
  const PointBox faces_box = box_of_all_points(fv_);
  edge_box_.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    edge_box_[e] = box_of_points(ev_, edges_[e]);
    if (!edge_box_[e].misses(faces_box)) near_edges_.push_back(e);
  }
}

void EdgeFaceScan::scan_face(FaceScan& face) {
  const auto& loop = faces_of_.poly.faces()[face.f];
  const auto epick = [](const Eigen::Vector3d& v) { return EpickPoint(v.x(), v.y(), v.z()); };
  face.f0 = epick(fv_[loop[0]]);
  face.f1 = epick(fv_[loop[1]]);
  face.f2 = epick(fv_[loop[2]]);
  // Plane sides are taken only for the end points of edges whose box meets the face's box
  // (most edges of a large hull are nowhere near a given face): memoised for this face.
  ++face_stamp_;
  for (const std::size_t e : near_edges_) {
    if (edge_box_[e].misses(face.box)) continue;  // disjoint boxes (exact double compares)
    edge_meets_face(e, face);
  }
}

int EdgeFaceScan::plane_side(const FaceScan& face, int v) {
  if (side_stamp_[v] != face_stamp_) {
    side_[v] = static_cast<int>(CGAL::orientation(face.f0, face.f1, face.f2, ep_[v]));
    side_stamp_[v] = face_stamp_;
  }
  return side_[v];
}

void EdgeFaceScan::prepare_face(FaceScan& face) {
  if (face.exact) return;
  const auto& loop = faces_of_.poly.faces()[face.f];
  face.exact.emplace(faces_of_, ev_, face.f);
  std::fill(have_value_.begin(), have_value_.end(), 0);
  m_iv_.clear();
  v_iv_.clear();
  CGAL::Protect_FPU_rounding<true> guard;
  face.n = faces_of_.face_normal<IV>(face.f);
  face.v0 = lift<IV>(fv_[loop[0]]);
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const IV3 vk = lift<IV>(fv_[loop[k]]);
    v_iv_.push_back(vk);
    m_iv_.push_back(cross(face.n, minus(lift<IV>(fv_[loop[(k + 1) % loop.size()]]), vk)));
  }
}

const IV& EdgeFaceScan::interval_value(int v, const FaceScan& face) {
  if (!have_value_[v]) {
    value_[v] = dot(face.n, minus(lift<IV>(ev_[v]), face.v0));  // caller holds the rounding guard
    have_value_[v] = 1;
  }
  return value_[v];
}

void EdgeFaceScan::edge_meets_face(std::size_t e, FaceScan& face) {
  const int i0 = edges_[e][0];
  const int i1 = edges_[e][1];
  const int s0 = plane_side(face, i0);
  const int s1 = plane_side(face, i1);
  if (s0 * s1 > 0) return;
  prepare_face(face);
  if (s0 == 0 && s1 == 0) {
    coplanar_edge_points(*face.exact, faces_of_, ev_[i0], ev_[i1], kind_, static_cast<int>(e),
                         face.f, out_);
    return;
  }
  // The crossing point as N / D: an end point on the plane, or the proper crossing.
  const bool at_end = s0 == 0 || s1 == 0;
  const int end = s0 == 0 ? i0 : i1;
  if (!maybe_inside(face, i0, i1, s0, at_end, end)) return;
  ExactPoint x = crossing_point(face, i0, i1, s0, at_end, end);
  if (!inside_exactly(face, x)) return;
  out_.add(std::move(x), kind_, static_cast<int>(e), face.f);
}

bool EdgeFaceScan::maybe_inside(FaceScan& face, int i0, int i1, int s0, bool at_end, int end) {
  undecided_.clear();
  CGAL::Protect_FPU_rounding<true> guard;
  IV3 num;
  IV den(1);
  if (at_end) {
    num = lift<IV>(ev_[end]);
  } else {
    const IV3 p = lift<IV>(ev_[i0]);
    const IV3 q = lift<IV>(ev_[i1]);
    const IV& sp = interval_value(i0, face);
    const IV& sq = interval_value(i1, face);
    for (int k = 0; k < 3; ++k) num[k] = sp * q[k] - sq * p[k];
    den = sp - sq;
  }
  const int sd = at_end ? 1 : s0;  // sign(D) = sign(s_p - s_q) = s_p
  const std::size_t loop_size = faces_of_.poly.faces()[face.f].size();
  for (std::size_t k = 0; k < loop_size; ++k) {
    const IV3 rel{num[0] - den * v_iv_[k][0], num[1] - den * v_iv_[k][1],
                  num[2] - den * v_iv_[k][2]};
    const Certain c = sign_of(dot(m_iv_[k], rel));
    if (c == Certain::kUnknown) {
      undecided_.push_back(k);
    } else if (certain_int(c) * sd < 0) {
      return false;  // -1: certainly outside
    }
  }
  return true;
}

ExactPoint EdgeFaceScan::crossing_point(FaceScan& face, int i0, int i1, int s0, bool at_end,
                                        int end) const {
  const auto& loop = faces_of_.poly.faces()[face.f];
  if (at_end) return exact_vertex(ev_[end]);
  ExactPoint x;
  if (undecided_.empty()) {
    if (const auto rounded = crossing_rounded_by_error_bound(ev_[i0], ev_[i1], fv_[loop[0]],
                                                             fv_[loop[1]], fv_[loop[2]])) {
      // proof: proofs/interference.md#crossing-by-error-bound
      x.rounded = *rounded;
      x.exact_known = false;
      x.crossing = {ev_[i0], ev_[i1], fv_[loop[0]], fv_[loop[1]], fv_[loop[2]]};
      return x;
    }
  }
  const Fast& sp = face.exact->side(i0);
  const Fast& sq = face.exact->side(i1);
  const Fast3 p = lift<Fast>(ev_[i0]);
  const Fast3 q = lift<Fast>(ev_[i1]);
  for (int k = 0; k < 3; ++k) x.num[k] = sp * q[k] - sq * p[k];
  x.den = sp - sq;
  if (s0 < 0) {  // keep den > 0
    for (auto& c : x.num) c = -c;
    x.den = -x.den;
  }
  return x;
}

bool EdgeFaceScan::inside_exactly(FaceScan& face, const ExactPoint& x) const {
  const auto& loop = faces_of_.poly.faces()[face.f];
  for (std::size_t k : undecided_) {
    const Fast3 vk = lift<Fast>(fv_[loop[k]]);
    const Fast3 rel{x.num[0] - x.den * vk[0], x.num[1] - x.den * vk[1], x.num[2] - x.den * vk[2]};
    if (exact_sign(dot(face.exact->edge_normal(k), rel)) < 0) return false;
  }
  return true;
}

void edge_face_points(const Hull& edges_of, const Hull& faces_of, InterferenceKind kind,
                      PointCollector& out) {
  EdgeFaceScan(edges_of, faces_of, kind, out).run();
}

/// Vertices of `of` inside closed `in`, exactly (all face planes n.x <= c).
void vertex_points(const Hull& of, const Hull& in, InterferenceKind kind, PointCollector& out) {
  const std::size_t faces = in.poly.faces().size();
  const auto& vs = of.poly.vertices();
  // A vertex outside the box of `in`'s vertices is outside `in` (exact double compares).
  Eigen::Vector3d in_lo = in.poly.vertices()[0], in_hi = in_lo;
  for (const auto& w : in.poly.vertices()) {
    in_lo = in_lo.cwiseMin(w);
    in_hi = in_hi.cwiseMax(w);
  }
  // Exact plane sides by CGAL's filtered orientation predicate (as in edge_face_points):
  // n.(x - v_0) has the sign of orientation(v_0, v_1, v_2, x). Inside the closed hull iff on
  // no face's outer side; the face that rejected the previous vertex is tried first.
  using EpickPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<std::array<EpickPoint, 3>> face_corners;
  std::size_t last_rejecting = 0;
  for (std::size_t v = 0; v < vs.size(); ++v) {
    if ((vs[v].array() < in_lo.array()).any() || (in_hi.array() < vs[v].array()).any()) {
      continue;
    }
    if (face_corners.empty()) {
      face_corners.reserve(faces);
      for (std::size_t f = 0; f < faces; ++f) {
        const auto corner = [&](int k) {
          const Eigen::Vector3d& c = in.vertex(static_cast<int>(f), k);
          return EpickPoint(c.x(), c.y(), c.z());
        };
        face_corners.push_back({corner(0), corner(1), corner(2)});
      }
    }
    const EpickPoint x(vs[v].x(), vs[v].y(), vs[v].z());
    const auto outside_of = [&](std::size_t f) {
      const auto& c = face_corners[f];
      return CGAL::orientation(c[0], c[1], c[2], x) == CGAL::POSITIVE;
    };
    bool inside = !outside_of(last_rejecting);
    for (std::size_t f = 0; f < faces && inside; ++f) {
      if (f != last_rejecting && outside_of(f)) {
        inside = false;
        last_rejecting = f;
      }
    }
    if (inside) out.add(exact_vertex(vs[v]), kind, static_cast<int>(v), -1);
  }
}

}  // namespace

std::vector<InterferencePoint> interference_points(const std::vector<Eigen::Vector3d>& a,
                                                   const std::vector<Eigen::Vector3d>& b) {
  return interference_points(ConvexPolytope::from_points(a), ConvexPolytope::from_points(b));
}

std::vector<InterferencePoint> interference_points(const ConvexPolytope& a,
                                                   const ConvexPolytope& b) {
  // proof: proofs/interference.md#interference-points
  const Hull A(a);
  const Hull B(b);
  std::vector<InterferencePoint> result;
  if (boxes_separate(a.vertices(), b.vertices())) return result;
  // No classify_hulls() first: the list is empty iff the hulls are disjoint (proof below), so
  // computing it decides separation too.
  PointCollector out;
  out.found.reserve(64);  // ExactPoints hold four Mpzf each: regrowing moves them all
  edge_face_points(A, B, InterferenceKind::kEdgeOfAOnFaceOfB, out);
  edge_face_points(B, A, InterferenceKind::kEdgeOfBOnFaceOfA, out);
  vertex_points(A, B, InterferenceKind::kVertexOfAInB, out);
  vertex_points(B, A, InterferenceKind::kVertexOfBInA, out);
  result.reserve(out.found.size());
  for (auto& [x, ip] : out.found) result.push_back(ip);
  return result;
}

// ---- separation witnesses -------------------------------------------------------------------------

double certified_lower_bound(const SeparationWitness& w) {
  // proof: proofs/interference.md#separation-witness
  if (!w.normal.allFinite() || w.normal.isZero(0.0)) {
    throw std::invalid_argument("separation witness needs a finite non-zero normal");
  }
  if (!std::isfinite(w.offset_a) || !std::isfinite(w.offset_b)) {
    throw std::invalid_argument("separation witness needs finite offsets");
  }
  if (!(w.offset_b > w.offset_a)) return 0.0;  // double comparison: exact
  // gap^2 >= r^2 |n|^2, decided exactly. The first estimate is within an ulp of the bound, so
  // intervals rarely decide it; CGAL::Mpzf (stack limbs, no malloc) is ~5x faster than Gmpzf
  // here, and the sphere slabs of every verifier step come through this function.
  using Small = CGAL::Mpzf;
  const Small gap = Small(w.offset_b) - Small(w.offset_a);
  const Small gap2 = gap * gap;
  const Small norm2 = Small(w.normal.x()) * Small(w.normal.x()) +
                      Small(w.normal.y()) * Small(w.normal.y()) +
                      Small(w.normal.z()) * Small(w.normal.z());
  const auto bound_holds = [&](double r) { return gap2 >= Small(r) * Small(r) * norm2; };
  double r = (0.5 * w.offset_b - 0.5 * w.offset_a) / w.normal.norm() * 2.0;
  if (!std::isfinite(r)) r = std::numeric_limits<double>::max();
  for (int it = 0; r > 0.0 && !bound_holds(r); ++it) r = step_down(r, it);
  return r;
}

bool check_witness_exactly(const std::vector<Eigen::Vector3d>& a,
                           const std::vector<Eigen::Vector3d>& b, const SeparationWitness& w,
                           double claimed_lower_bound) {
  // proof: proofs/interference.md#separation-witness
  if (a.empty() || b.empty()) return false;
  if (!w.normal.allFinite() || w.normal.isZero(0.0)) return false;
  if (!std::isfinite(w.offset_a) || !std::isfinite(w.offset_b)) return false;
  if (std::isnan(claimed_lower_bound) || w.offset_a > w.offset_b) return false;
  for (const auto& p : a) if (!p.allFinite()) return false;
  for (const auto& p : b) if (!p.allFinite()) return false;

  const Exact3 n = lift<Exact>(w.normal);
  std::vector<std::size_t> unsure_a, unsure_b;
  bool violated = false;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    const IV3 ni = lift<IV>(w.normal);
    for (std::size_t i = 0; i < a.size() && !violated; ++i) {
      const IV d = dot(ni, lift<IV>(a[i]));
      if (d.inf() > w.offset_a) violated = true;
      else if (d.sup() > w.offset_a) unsure_a.push_back(i);
    }
    for (std::size_t i = 0; i < b.size() && !violated; ++i) {
      const IV d = dot(ni, lift<IV>(b[i]));
      if (d.sup() < w.offset_b) violated = true;
      else if (d.inf() < w.offset_b) unsure_b.push_back(i);
    }
  }
  if (violated) return false;
  const Exact oa(w.offset_a), ob(w.offset_b);
  for (std::size_t i : unsure_a) if (dot(n, lift<Exact>(a[i])) > oa) return false;
  for (std::size_t i : unsure_b) if (dot(n, lift<Exact>(b[i])) < ob) return false;
  if (claimed_lower_bound <= 0.0) return true;  // gap >= 0 >= claimed * |n|
  if (std::isinf(claimed_lower_bound)) return false;
  const Exact gap = ob - oa;
  const Exact claimed(claimed_lower_bound);
  return gap * gap >= claimed * claimed * dot(n, n);
}

namespace {

using HKernel = CGAL::Homogeneous<double>;
// ET AND NT exact (Gmpzf). Measured: with NT = double (cgal-notes' Homogeneous<double>,
// MP_Float, double) the filtered pricing stops early on near-contact pairs (distance 1e-9)
// and reports a squared distance up to 1e-6 relatively TOO LARGE - unsound for a lower bound.
// See SeparationWitness.RandomWitnessesAreSoundTightAndTamperEvident.
using DistanceTraits = CGAL::Polytope_distance_d_traits_3<HKernel, CGAL::Gmpzf, CGAL::Gmpzf>;
using PolytopeDistance = CGAL::Polytope_distance_d<DistanceTraits>;

std::vector<HKernel::Point_3> homogeneous_points(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<HKernel::Point_3> out;
  out.reserve(pts.size());
  for (const auto& p : pts) out.emplace_back(p.x(), p.y(), p.z(), 1.0);
  return out;
}

/// The witness along direction n (double): exact support values rounded outward.
std::optional<SeparationWitness> witness_along(const std::vector<Eigen::Vector3d>& a,
                                               const std::vector<Eigen::Vector3d>& b,
                                               const Eigen::Vector3d& n) {
  if (!n.allFinite() || n.isZero(0.0)) return std::nullopt;
  const Exact3 ne = lift<Exact>(n);
  Exact max_a = dot(ne, lift<Exact>(a.front()));
  for (const auto& p : a) {
    const Exact d = dot(ne, lift<Exact>(p));
    if (d > max_a) max_a = d;
  }
  Exact min_b = dot(ne, lift<Exact>(b.front()));
  for (const auto& p : b) {
    const Exact d = dot(ne, lift<Exact>(p));
    if (d < min_b) min_b = d;
  }
  SeparationWitness w{n, round_up(max_a), round_down(min_b)};
  if (!std::isfinite(w.offset_a) || !std::isfinite(w.offset_b) || !(w.offset_a < w.offset_b)) {
    return std::nullopt;
  }
  return w;
}

}  // namespace

std::optional<SeparationWitness> exact_separation_witness(const std::vector<Eigen::Vector3d>& a,
                                                          const std::vector<Eigen::Vector3d>& b) {
  // proof: proofs/interference.md#separation-witness
  require_points(a, "exact_separation_witness");
  require_points(b, "exact_separation_witness");
  const auto ha = homogeneous_points(a);
  const auto hb = homogeneous_points(b);
  const PolytopeDistance distance(ha.begin(), ha.end(), hb.begin(), hb.end());
  if (CGAL::is_zero(distance.squared_distance_numerator())) return std::nullopt;

  // Closest-point direction q - p (common homogeneous denominator).
  std::vector<Exact> p(distance.realizing_point_p_coordinates_begin(),
                       distance.realizing_point_p_coordinates_end());
  std::vector<Exact> q(distance.realizing_point_q_coordinates_begin(),
                       distance.realizing_point_q_coordinates_end());
  if (p.size() != 4 || q.size() != 4 || p[3] != q[3]) {
    throw std::logic_error("Polytope_distance_d: unexpected realizing point representation");
  }
  const double sign = CGAL::sign(p[3]) == CGAL::NEGATIVE ? -1.0 : 1.0;
  Eigen::Vector3d n(CGAL::to_double(q[0] - p[0]), CGAL::to_double(q[1] - p[1]),
                    CGAL::to_double(q[2] - p[2]));
  n *= sign;
  if (auto w = witness_along(a, b, n)) return w;

  // Fallback: the best exact SAT axis (rounded), for gaps that the rounded direction lost.
  const ConvexPolytope pa = ConvexPolytope::from_points(a);
  const ConvexPolytope pb = ConvexPolytope::from_points(b);
  const Hull A(pa);
  const Hull B(pb);
  std::optional<SeparationWitness> best;
  double best_bound = -1.0;
  for (const Axis& axis : candidate_axes(A, B)) {
    const Exact3 ne = axis_vector<Exact>(axis, A, B);
    const Eigen::Vector3d nd(CGAL::to_double(ne[0]), CGAL::to_double(ne[1]),
                             CGAL::to_double(ne[2]));
    for (const Eigen::Vector3d& dir : {nd, Eigen::Vector3d(-nd)}) {
      if (auto w = witness_along(a, b, dir)) {
        const double bound = certified_lower_bound(*w);
        if (bound > best_bound) {
          best_bound = bound;
          best = w;
        }
      }
    }
  }
  return best;
}

double exact_distance_squared_lower(const std::vector<Eigen::Vector3d>& a,
                                    const std::vector<Eigen::Vector3d>& b) {
  require_points(a, "exact_distance_squared_lower");
  require_points(b, "exact_distance_squared_lower");
  const auto ha = homogeneous_points(a);
  const auto hb = homogeneous_points(b);
  const PolytopeDistance distance(ha.begin(), ha.end(), hb.begin(), hb.end());
  Exact num = distance.squared_distance_numerator();
  Exact den = distance.squared_distance_denominator();
  if (CGAL::is_zero(num)) return 0.0;
  if (CGAL::sign(den) == CGAL::NEGATIVE) {
    num = -num;
    den = -den;
  }
  double lower;
  {
    CGAL::Protect_FPU_rounding<true> guard;
    lower = (IV(CGAL::to_interval(num)) / IV(CGAL::to_interval(den))).inf();
  }
  // Never trust a conversion: step down until lower * den <= num holds exactly, then up while
  // the next double still satisfies it (so exactly representable distances come out exact).
  const double inf = std::numeric_limits<double>::infinity();
  lower = std::max(0.0, lower);
  if (!std::isfinite(lower)) lower = std::numeric_limits<double>::max();
  for (int it = 0; lower > 0.0 && Exact(lower) * den > num; ++it) lower = step_down(lower, it);
  for (int step = 0; step < 4; ++step) {
    const double up = std::nextafter(lower, inf);
    if (!(Exact(up) * den <= num)) break;
    lower = up;
  }
  return lower;
}

}  // namespace grpvss::geometry
