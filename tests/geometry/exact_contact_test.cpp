#include "grpvss/exact/exact_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <map>
#include <set>
#include <string>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "support/geometry_reference.hpp"
#include "support/random_shapes.hpp"
#include "support/rounding_reference.hpp"

namespace grpvss::geometry {
namespace {

using testing::Points;

Points shifted(const Points& pts, const Eigen::Vector3d& t) {
  return testing::transformed(pts, Eigen::Matrix3d::Identity(), t);
}

/// A plain double-precision SAT (what a naive implementation does): all face normals and all
/// edge x edge directions of the (exact) hulls, projections in double, ties read as touching.
Contact double_sat(const Points& a, const Points& b) {
  const ConvexPolytope A = ConvexPolytope::from_points(a);
  const ConvexPolytope B = ConvexPolytope::from_points(b);
  std::vector<Eigen::Vector3d> axes;
  for (const auto* P : {&A, &B}) {
    for (const auto& f : P->faces()) {
      const auto& v = P->vertices();
      axes.push_back((v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]));
    }
  }
  for (const auto& ea : A.edges()) {
    for (const auto& eb : B.edges()) {
      const Eigen::Vector3d n = (A.vertices()[ea[1]] - A.vertices()[ea[0]])
                                    .cross(B.vertices()[eb[1]] - B.vertices()[eb[0]]);
      if (!n.isZero(0.0)) axes.push_back(n);
    }
  }
  bool touching = false;
  for (const auto& n : axes) {
    double a_min = std::numeric_limits<double>::infinity(), a_max = -a_min;
    double b_min = a_min, b_max = -a_min;
    for (const auto& p : A.vertices()) {
      a_min = std::min(a_min, n.dot(p));
      a_max = std::max(a_max, n.dot(p));
    }
    for (const auto& p : B.vertices()) {
      b_min = std::min(b_min, n.dot(p));
      b_max = std::max(b_max, n.dot(p));
    }
    if (a_max < b_min || b_max < a_min) return Contact::kSeparated;
    if (a_max == b_min || b_max == a_min) touching = true;
  }
  return touching ? Contact::kTouching : Contact::kOverlapping;
}

Contact expected_for_gap(double gap) {
  return gap > 0 ? Contact::kSeparated : gap == 0 ? Contact::kTouching : Contact::kOverlapping;
}

const double kGaps[] = {0.0, 0x1p-40, -0x1p-40, 1e-12, -1e-12, 0.25, -0.25};

TEST(ClassifyExact, FaceFaceContactAtTinyGaps) {
  const Points a = testing::box({0, 0, 0}, {1, 1, 1});
  for (double gap : kGaps) {
    SCOPED_TRACE(gap);
    // B's low x face is at fl(1 + gap); the true gap is that minus 1.
    const double lo = 1.0 + gap;
    const Points b = testing::box({lo, 0.25, -0.5}, {2.0, 1.25, 0.5});
    const Contact expected = expected_for_gap(lo - 1.0);
    EXPECT_EQ(classify_exact(a, b), expected);
    EXPECT_EQ(classify_exact(b, a), expected);
    EXPECT_EQ(testing::reference_contact(a, b), expected);
  }
}

TEST(ClassifyExact, EdgeEdgeContactAtTinyGaps) {
  // A's top edge runs along y at x = 0; B's edge runs along z at x = gap. Only the
  // edge x edge axis (1, 0, 0) separates them.
  const Points a{{0, -1, 0}, {0, 1, 0}, {-1, 0, 1}, {-1, 0, -1}};
  for (double gap : kGaps) {
    SCOPED_TRACE(gap);
    const Points b{{gap, 0, -1}, {gap, 0, 1}, {1 + gap, -1, 0}, {1 + gap, 1, 0}};
    EXPECT_EQ(classify_exact(a, b), expected_for_gap(gap));
    EXPECT_EQ(classify_exact(b, a), expected_for_gap(gap));
    EXPECT_EQ(testing::reference_contact(a, b), expected_for_gap(gap));
  }
}

TEST(ClassifyExact, VertexFaceContactAtTinyGaps) {
  const Points octahedron{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (double gap : kGaps) {
    SCOPED_TRACE(gap);
    const double lo = 1.0 + gap;
    const Points b = testing::box({lo, -1, -1}, {3, 1, 1});
    const Contact expected = expected_for_gap(lo - 1.0);
    EXPECT_EQ(classify_exact(octahedron, b), expected);
    EXPECT_EQ(classify_exact(b, octahedron), expected);
    EXPECT_EQ(testing::reference_contact(octahedron, b), expected);
  }
}

TEST(ClassifyExact, ThinSolidApexAgainstAFace) {
  // A tetrahedron 2^-60 high: its apex is the only point above z = 0.
  const Points sliver{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0x1p-60}};
  const struct {
    double lo;
    Contact expected;
  } cases[] = {{0x1p-60, Contact::kTouching},
               {0x1p-61, Contact::kOverlapping},
               {0x1p-59, Contact::kSeparated}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.lo);
    const Points b = testing::box({-1, -1, c.lo}, {2, 2, 1});
    EXPECT_EQ(classify_exact(sliver, b), c.expected);
    EXPECT_EQ(testing::reference_contact(sliver, b), c.expected);
    EXPECT_EQ(interference_points(sliver, b).empty(), c.expected == Contact::kSeparated);
  }
}

TEST(ClassifyExact, ContainmentEitherWayIsOverlapping) {
  const Points big = testing::box({0, 0, 0}, {4, 4, 4});
  const Points small = testing::box({1, 1, 1}, {2, 2, 2});
  const Points corner = testing::box({0, 0, 0}, {1, 1, 1});  // inside, sharing three faces
  EXPECT_EQ(classify_exact(big, small), Contact::kOverlapping);
  EXPECT_EQ(classify_exact(small, big), Contact::kOverlapping);
  EXPECT_EQ(classify_exact(big, corner), Contact::kOverlapping);
  EXPECT_EQ(classify_exact(corner, big), Contact::kOverlapping);
  EXPECT_EQ(classify_exact(big, big), Contact::kOverlapping);
  // Edge-face tests alone see nothing here; vertices inside report the containment.
  const auto points = interference_points(big, small);
  ASSERT_EQ(points.size(), 8u);
  for (const auto& p : points) EXPECT_EQ(p.kind, InterferenceKind::kVertexOfBInA);
}

TEST(ClassifyExact, DegenerateInputThrows) {
  const Points flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  EXPECT_THROW(classify_exact(flat, testing::box({0, 0, 0}, {1, 1, 1})), DegenerateHullError);
  EXPECT_THROW(interference_points(testing::box({0, 0, 0}, {1, 1, 1}), flat),
               DegenerateHullError);
}

struct PairCase {
  Points a, b;
  std::string label;
};

/// Random placed pairs: rotated IBM 7545 hulls and random (rotated or dyadic axis-aligned)
/// boxes, translated within a range where roughly half of them meet.
std::vector<PairCase> random_pairs(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // Centre each hull at its vertex mean (exactly representable shifts are not needed: the
  // centred points are simply new inputs).
  auto hulls = testing::ibm7545_hulls();
  for (auto& h : hulls) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : h) mean += p;
    mean /= static_cast<double>(h.size());
    for (auto& p : h) p -= mean;
  }
  std::vector<PairCase> out;
  auto random_box = [&](bool rotate) {
    Eigen::Vector3d lo, hi;
    for (int k = 0; k < 3; ++k) {
      // Corners on a 1/2 grid make exact face, edge and vertex contacts likely.
      lo[k] = std::floor(unit(rng) * 10.0) / 2.0 - 2.5;
      hi[k] = lo[k] + 0.5 + std::floor(unit(rng) * 8.0) / 2.0;
    }
    Points p = testing::box(lo, hi);
    if (rotate) p = testing::transformed(p, testing::random_rotation(rng), {0, 0, 0});
    return p;
  };
  for (int i = 0; i < count; ++i) {
    PairCase c;
    const int kind = i % 3;
    if (kind == 0) {
      const auto& ha = hulls[rng() % hulls.size()];
      const auto& hb = hulls[rng() % hulls.size()];
      const Eigen::Vector3d t(unit(rng) * 24 - 12, unit(rng) * 24 - 12, unit(rng) * 24 - 12);
      c.a = testing::transformed(ha, testing::random_rotation(rng), {0, 0, 0});
      c.b = testing::transformed(hb, testing::random_rotation(rng), t);
      c.label = "ibm pair " + std::to_string(i);
    } else if (kind == 1) {
      c.a = random_box(false);
      c.b = random_box(false);
      c.label = "dyadic boxes " + std::to_string(i);
    } else {
      c.a = random_box(true);
      c.b = random_box(true);
      c.label = "rotated boxes " + std::to_string(i);
    }
    out.push_back(std::move(c));
  }
  return out;
}

TEST(ClassifyExact, AgreesWithIndependentReferenceOnRandomPairs) {
  int counts[3] = {0, 0, 0};
  for (const PairCase& c : random_pairs(1988, 1500)) {
    const Contact expected = testing::reference_contact(c.a, c.b);
    ASSERT_EQ(classify_exact(c.a, c.b), expected) << c.label;
    ASSERT_EQ(classify_exact(ConvexPolytope::from_points(c.b), ConvexPolytope::from_points(c.a)),
              expected)
        << c.label;
    ++counts[static_cast<int>(expected)];
  }
  std::printf("random pairs: %d separated, %d touching, %d overlapping\n", counts[0], counts[1],
              counts[2]);
  // The sample exercises all three outcomes.
  EXPECT_GT(counts[0], 300);
  EXPECT_GT(counts[1], 20);
  EXPECT_GT(counts[2], 300);
}

/// Near-contact pairs: translate A along the exact closest-point direction so that it (almost)
/// touches B, plus or minus 1e-12 and 2^-40 of the gap. Rounding of the translated coordinates
/// makes the outcome a coin toss that only exact arithmetic decides; a plain double SAT gets
/// some of them wrong, classify_exact none.
TEST(ClassifyExact, AgreesWithReferenceOnNearContactWherePlainDoubleFails) {
  int double_wrong = 0, checked = 0;
  for (const PairCase& c : random_pairs(7545, 300)) {
    if (testing::reference_contact(c.a, c.b) != Contact::kSeparated) continue;
    Eigen::Vector3d p, q;
    testing::reference_closest_points(c.a, c.b, p, q);
    const Eigen::Vector3d v = q - p;
    for (double s : {0.0, 1e-12, -1e-12, 0x1p-40, -0x1p-40}) {
      const Points a = shifted(c.a, v * (1.0 + s));
      const Contact expected = testing::reference_contact(a, c.b);
      ASSERT_EQ(classify_exact(a, c.b), expected) << c.label << " s=" << s;
      ASSERT_EQ(classify_exact(c.b, a), expected) << c.label << " s=" << s;
      if (double_sat(a, c.b) != expected) ++double_wrong;
      ++checked;
    }
  }
  std::printf("near-contact pairs: %d checked, plain double SAT wrong on %d\n", checked,
              double_wrong);
  EXPECT_GT(checked, 500);
  EXPECT_GT(double_wrong, 0);
}

/// Regression case found by the near-contact search (seed 7545, "rotated boxes 8"): two rotated
/// boxes a hair apart. Plain double SAT says they overlap; they are separated.
TEST(ClassifyExact, SeparatedPairThatPlainDoubleSatCallsOverlapping) {
  const Points a{{0x1.a1108db46f91ap-1, 0x1.07da3fcfe9971p+1, 0x1.ef7b9487ae894p-1},
                 {-0x1.36211d03a992ap+1, 0x1.8b942943af7a4p-1, 0x1.4bdddd37ba01dp+0},
                 {0x1.9cbef3a6ac1a1p+0, -0x1.3edcdbafe50f8p-3, 0x1.0e6eca9c0e316p-3},
                 {-0x1.a00b8d3aded4p+0, -0x1.71c60673f812ep+0, 0x1.d7b7b11d920d8p-2},
                 {0x1.055b70077bff9p+0, 0x1.c837f43bd870cp+0, 0x1.e7d091a1525d5p+0},
                 {-0x1.1bb7886d07774p+1, 0x1.f93624f773ffp-2, 0x1.1df8524a9a8d4p+1},
                 {0x1.d1921cd3f050dp+0, -0x1.bd609b67dd7d2p-2, 0x1.11e0a0b0fcdeep+0},
                 {-0x1.6b38640d9a9d4p+0, -0x1.b94291d7f2d04p+0, 0x1.6600b3a4df9c1p+0}};
  const Points b{{-0x1.404be50d2cb28p+0, -0x1.80051d2f14768p+1, -0x1.eb567831247a9p+0},
                 {-0x1.2d8195322e87dp+0, -0x1.f6f22e6720906p+1, -0x1.8e8d28f4d653p+0},
                 {-0x1.1ce92c764f448p-2, -0x1.6d423c7d26a74p+1, -0x1.bd9726ebe0fe7p+0},
                 {-0x1.a37fda14ad334p-3, -0x1.e42f4db532c1p+1, -0x1.60cdd7af92d6ep+0},
                 {-0x1.0254a04d69427p+1, -0x1.cfd5335f00babp+0, 0x1.483e90c75faa6p+0},
                 {-0x1.f1def0bfd45a2p+0, -0x1.5ed7aae78c773p+1, 0x1.a507e003add1ep+0},
                 {-0x1.0b97a6ab39a38p+0, -0x1.aa4f71fb251c1p+0, 0x1.75fde20ca3269p+0},
                 {-0x1.f19aada076f18p-1, -0x1.4c14ca359ea7dp+1, 0x1.d2c73148f14e2p+0}};
  EXPECT_EQ(double_sat(a, b), Contact::kOverlapping);  // wrong
  EXPECT_EQ(testing::reference_contact(a, b), Contact::kSeparated);
  EXPECT_EQ(classify_exact(a, b), Contact::kSeparated);
  EXPECT_EQ(classify_exact(b, a), Contact::kSeparated);
  EXPECT_TRUE(interference_points(a, b).empty());
}

TEST(InterferencePoints, BoxThroughFaceGivesCrossingsAndContainedVertices) {
  const Points a = testing::box({0, 0, 0}, {2, 2, 2});
  const Points b = testing::box({1, 0.5, 0.5}, {3, 1.5, 1.5});
  const auto points = interference_points(a, b);
  std::vector<std::array<double, 3>> crossings, inside;
  for (const auto& ip : points) {
    if (ip.kind == InterferenceKind::kEdgeOfBOnFaceOfA) {
      crossings.push_back({ip.point.x(), ip.point.y(), ip.point.z()});
    } else if (ip.kind == InterferenceKind::kVertexOfBInA) {
      inside.push_back({ip.point.x(), ip.point.y(), ip.point.z()});
    } else {
      ADD_FAILURE() << "unexpected kind " << to_string(ip.kind);
    }
  }
  std::sort(crossings.begin(), crossings.end());
  std::sort(inside.begin(), inside.end());
  using P = std::vector<std::array<double, 3>>;
  EXPECT_EQ(crossings, (P{{2, 0.5, 0.5}, {2, 0.5, 1.5}, {2, 1.5, 0.5}, {2, 1.5, 1.5}}));
  EXPECT_EQ(inside, (P{{1, 0.5, 0.5}, {1, 0.5, 1.5}, {1, 1.5, 0.5}, {1, 1.5, 1.5}}));
}

TEST(InterferencePoints, EdgeCrossingARotatedFaceIsExactBeforeRounding) {
  // Edge from (0.1, 0.1, -1) to (0.1, 0.1, 1) through the tetrahedron face x + y + z = 1/3 ...
  const Points tetra{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const Points needle{{0.125, 0.125, -1}, {0.125, 0.125, 2}, {0.25, 0.125, -1}, {0.125, 0.25, -1}};
  const auto points = interference_points(needle, tetra);
  bool found_top = false;
  for (const auto& ip : points) {
    if (ip.kind == InterferenceKind::kEdgeOfAOnFaceOfB && ip.point.z() == 0.75) found_top = true;
  }
  EXPECT_TRUE(found_top);  // x + y + z = 1 at z = 1 - 0.25 = 0.75, exactly representable
}

TEST(InterferencePoints, NonEmptyExactlyWhenNotSeparatedAndPointsLieInBoth) {
  int nonempty = 0;
  for (const PairCase& c : random_pairs(42, 240)) {
    const Contact contact = classify_exact(c.a, c.b);
    const auto points = interference_points(c.a, c.b);
    EXPECT_EQ(points.empty(), contact == Contact::kSeparated) << c.label;
    if (points.empty()) continue;
    ++nonempty;
    double scale = 1.0;
    for (const auto& p : c.a) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    for (const auto& ip : points) {
      // Rounded from an exact point of A ∩ B: within a few ulps of both hulls.
      EXPECT_LE(testing::reference_distance({ip.point}, c.a), 1e-13 * scale) << c.label;
      EXPECT_LE(testing::reference_distance({ip.point}, c.b), 1e-13 * scale) << c.label;
    }
  }
  EXPECT_GT(nonempty, 50);
}

TEST(InterferencePoints, EveryProperCrossingIsItsExactValueRoundedToNearest) {
  // End to end through the error-bound filter and the exact path alike
  // (proofs/interference.md#crossing-by-error-bound): each reported edge-face crossing whose
  // edge ends lie strictly on opposite sides of its face's plane equals the GMP-rational
  // reference crossing of that edge and plane, rounded to nearest.
  int checked = 0;
  for (const PairCase& c : random_pairs(2026, 600)) {
    const ConvexPolytope A = ConvexPolytope::from_points(c.a);
    const ConvexPolytope B = ConvexPolytope::from_points(c.b);
    for (const auto& ip : interference_points(A, B)) {
      const bool a_edge = ip.kind == InterferenceKind::kEdgeOfAOnFaceOfB;
      if (!a_edge && ip.kind != InterferenceKind::kEdgeOfBOnFaceOfA) continue;
      const ConvexPolytope& edges_of = a_edge ? A : B;
      const ConvexPolytope& faces_of = a_edge ? B : A;
      const auto& edge = edges_of.edges()[static_cast<std::size_t>(ip.feature_first)];
      const auto& loop = faces_of.faces()[static_cast<std::size_t>(ip.feature_second)];
      const auto& p = edges_of.vertices()[static_cast<std::size_t>(edge[0])];
      const auto& q = edges_of.vertices()[static_cast<std::size_t>(edge[1])];
      const auto& fv = faces_of.vertices();
      const auto& f0 = fv[static_cast<std::size_t>(loop[0])];
      const auto& f1 = fv[static_cast<std::size_t>(loop[1])];
      const auto& f2 = fv[static_cast<std::size_t>(loop[2])];
      if (testing::reference_plane_side(p, f0, f1, f2) *
              testing::reference_plane_side(q, f0, f1, f2) >= 0) {
        continue;  // an end point on the plane, or the edge in it: not a proper crossing
      }
      ++checked;
      EXPECT_EQ(ip.point, testing::reference_crossing(p, q, f0, f1, f2)) << c.label;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(InterferencePoints, FaceSharingBoxesGiveExactlyTheCornersOfTheirIntersection) {
  // Every edge of either box lies in a face plane of the other or crosses at a corner: the
  // coplanar-edge and end-point-on-plane paths, and duplicate removal within each kind.
  const Points a = testing::box({0, 0, 0}, {2, 2, 2});
  const Points b = testing::box({1, 0, 0}, {3, 2, 2});
  std::set<std::array<double, 3>> corners;
  for (double x : {1.0, 2.0}) {
    for (double y : {0.0, 2.0}) {
      for (double z : {0.0, 2.0}) corners.insert({x, y, z});
    }
  }
  std::set<std::array<double, 3>> seen;
  std::map<InterferenceKind, std::set<std::array<double, 3>>> per_kind;
  std::map<InterferenceKind, int> count;
  for (const auto& ip : interference_points(a, b)) {
    const std::array<double, 3> x{ip.point.x(), ip.point.y(), ip.point.z()};
    EXPECT_EQ(corners.count(x), 1u) << x[0] << " " << x[1] << " " << x[2];
    seen.insert(x);
    per_kind[ip.kind].insert(x);
    ++count[ip.kind];
  }
  EXPECT_EQ(seen, corners);
  for (const auto& [kind, points] : per_kind) {
    EXPECT_EQ(static_cast<int>(points.size()), count[kind]) << "duplicate in " << to_string(kind);
  }
}

TEST(InterferencePoints, ExactVertexContactOfRotatedPrismsIsThatVertexOnly) {
  // B is A reflected through its extreme vertex v (exact on a 2^-20 grid): A and B meet in v
  // alone. Intervals cannot decide any of the sign tests at v; the exact fallback must, and
  // every reported point must be v bit for bit.
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    std::mt19937_64 rng(seed);
    Points a = test::random_prism(rng, Eigen::Vector3d::Zero(), 2.0);
    for (auto& p : a) {
      for (int k = 0; k < 3; ++k) p[k] = std::ldexp(std::round(std::ldexp(p[k], 20)), -20);
    }
    const Eigen::Vector3d n = Eigen::Vector3d(1.0, 0.5, 0.25).normalized();
    const Eigen::Vector3d v = a[support_index(a, n)];
    Points b;
    for (const auto& p : a) b.push_back(2.0 * v - p);
    ASSERT_EQ(classify_exact(a, b), Contact::kTouching) << seed;
    const auto points = interference_points(a, b);
    ASSERT_FALSE(points.empty()) << seed;
    for (const auto& ip : points) EXPECT_EQ(ip.point, v) << seed << " " << to_string(ip.kind);
    // Pushed 2^-30 apart along n they separate; 2^-30 together they overlap.
    EXPECT_TRUE(interference_points(a, test::translated(b, std::ldexp(1.0, -30) * n)).empty());
    EXPECT_FALSE(interference_points(a, test::translated(b, -std::ldexp(1.0, -30) * n)).empty());
  }
}

}  // namespace
}  // namespace grpvss::geometry
