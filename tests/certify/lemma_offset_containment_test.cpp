// Checks proofs/offset-containment.md with exact rationals: the face-plane test for
// B(0,Delta) in P, the expanded-separation distance bound, and the a-posteriori acceptance of a
// rounded Minkowski sum.

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::Q;
using lemma_ref::Vec3;
using Q3 = std::array<Q, 3>;

struct OffsetPlane {
  Q3 n;
  Q c;  // n.x <= c
};

// proofs/offset-containment.md#lemma-ball-in-polytope: c >= Delta |n|, decided exactly.
bool plane_contains_ball(const OffsetPlane& f, const Q& delta) {
  return f.c >= 0 && f.c * f.c >= delta * delta * lemma_ref::dot_q(f.n, f.n);
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3 v{g(rng), g(rng), g(rng)};
  return lemma_ref::scale(v, 1.0 / lemma_ref::norm(v));
}

// A double point of the closed ball B(0, delta), verified exactly (shrunk until it is).
Vec3 ball_point(const Vec3& dir, double radius, double delta) {
  Vec3 x = lemma_ref::scale(dir, radius);
  while (lemma_ref::dot_q(lemma_ref::exact(x), lemma_ref::exact(x)) > Q(delta) * Q(delta))
    x = lemma_ref::scale(x, 1.0 - 1e-15);
  return x;
}

TEST(LemmaOffsetContainment, PassingPlanesContainSampledBallPoints) {
  std::mt19937 rng(101);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  int passing = 0, failing = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double delta = 0.01 + 2.0 * u01(rng);
    const Vec3 n{u(rng), u(rng), u(rng)};
    // Offsets around Delta |n|: exactly rounded, slightly above, slightly below.
    const double factor = (trial % 3 == 0) ? 1.0 : (trial % 3 == 1 ? 1.0 + 1e-9 : 1.0 - 1e-9);
    const OffsetPlane f{lemma_ref::exact(n), Q(delta * lemma_ref::norm(n) * factor)};
    if (plane_contains_ball(f, Q(delta))) {
      ++passing;
      for (int k = 0; k < 300; ++k) {
        const double radius = (k % 3 == 0) ? delta : delta * std::cbrt(u01(rng));
        // Half the samples aim at the plane, where containment is tightest.
        const Vec3 dir = (k % 2 == 0) ? lemma_ref::scale(n, 1.0 / lemma_ref::norm(n)) : random_unit(rng);
        const Vec3 x = ball_point(dir, radius, delta);
        EXPECT_LE(lemma_ref::dot_q(f.n, lemma_ref::exact(x)), f.c) << "trial " << trial;
      }
    } else {
      ++failing;
      // A plane that fails by a clear margin really cuts the ball: the ball point in direction n
      // is outside it. (Planes within an ulp of Delta|n| cannot be probed with double points.)
      if (trial % 3 != 2) continue;
      const Vec3 x = ball_point(lemma_ref::scale(n, 1.0 / lemma_ref::norm(n)), delta, delta);
      EXPECT_GT(lemma_ref::dot_q(f.n, lemma_ref::exact(x)), f.c) << "trial " << trial;
    }
  }
  EXPECT_GT(passing, 100);
  EXPECT_GT(failing, 50);
}

TEST(LemmaOffsetContainment, CubeOfHalfSideDeltaPassesAndSlightlySmallerFails) {
  for (double delta : {0.5, 0.1, 1.0 / 3.0, 7.25}) {
    for (double half_side : {delta, delta * (1.0 - 1e-12)}) {
      bool all_pass = true;
      for (int axis = 0; axis < 3; ++axis) {
        for (int sign : {-1, 1}) {
          OffsetPlane f{{Q(0), Q(0), Q(0)}, Q(half_side)};
          f.n[axis] = sign;
          all_pass = all_pass && plane_contains_ball(f, Q(delta));
        }
      }
      EXPECT_EQ(all_pass, half_side == delta) << "delta " << delta << " half side " << half_side;
    }
  }
}

const std::array<Vec3, 8> kCubeCorners{{{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1},
                                        {-1, -1, 1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, 1}}};

std::vector<Vec3> random_offset_points(std::mt19937& rng, int count, const Vec3& centre, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int k = 0; k < count; ++k)
    pts.push_back(lemma_ref::add(centre, {spread * u(rng), spread * u(rng), spread * u(rng)}));
  return pts;
}

Vec3 random_in_offset_hull(std::mt19937& rng, const std::vector<Vec3>& pts) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<double> w(pts.size());
  double sum = 0.0;
  for (double& x : w) sum += (x = u01(rng) * u01(rng) * u01(rng));  // favour vertices
  Vec3 p{0, 0, 0};
  for (std::size_t k = 0; k < pts.size(); ++k) p = lemma_ref::add(p, lemma_ref::scale(pts[k], w[k] / sum));
  return p;
}

TEST(LemmaOffsetContainment, ExpandedSeparationGivesDistanceAtLeastDeltaPlusMargin) {
  std::mt19937 rng(202);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int certified = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double delta = 0.05 + 0.5 * u01(rng);
    const auto a_pts = random_offset_points(rng, 6, {0, 0, 0}, 1.0);
    const Vec3 offset = lemma_ref::scale(random_unit(rng), 2.0 + 2.0 * u01(rng));
    const auto o_pts = random_offset_points(rng, 6, offset, 1.0);
    // A (+) P with P the cube of half-side delta: vertices a + delta * corner.
    std::vector<Vec3> expanded;
    for (const Vec3& a : a_pts)
      for (const Vec3& corner : kCubeCorners) expanded.push_back(lemma_ref::add(a, lemma_ref::scale(corner, delta)));
    const Vec3 n = lemma_ref::add(offset, lemma_ref::scale(random_unit(rng), 0.3));
    const Q3 nq = lemma_ref::exact(n);
    Q a0 = lemma_ref::dot_q(nq, lemma_ref::exact(expanded[0]));
    for (const Vec3& e : expanded) a0 = std::max(a0, lemma_ref::dot_q(nq, lemma_ref::exact(e)));
    Q b0 = lemma_ref::dot_q(nq, lemma_ref::exact(o_pts[0]));
    for (const Vec3& o : o_pts) b0 = std::min(b0, lemma_ref::dot_q(nq, lemma_ref::exact(o)));
    if (!(b0 > a0)) continue;
    // Margin c <= (b0 - a0)/|n|, verified exactly (proofs/separation-witness.md#lemma-witness).
    double c = (b0 - a0).convert_to<double>() / lemma_ref::norm(n);
    while (Q(c) * Q(c) * lemma_ref::dot_q(nq, nq) > (b0 - a0) * (b0 - a0)) c = std::nextafter(c, 0.0);
    ++certified;
    // Every sampled pair distance is >= the true distance, which the lemma says is >= delta + c.
    double sampled_min = 1e300;
    for (const Vec3& a : a_pts)
      for (const Vec3& o : o_pts) sampled_min = std::min(sampled_min, lemma_ref::norm(lemma_ref::sub(a, o)));
    for (int k = 0; k < 2000; ++k)
      sampled_min = std::min(sampled_min,
                             lemma_ref::norm(lemma_ref::sub(random_in_offset_hull(rng, a_pts), random_in_offset_hull(rng, o_pts))));
    EXPECT_GE(sampled_min, delta + c - 1e-12) << "trial " << trial;
  }
  EXPECT_GT(certified, 100);
}

// All supporting planes through three non-collinear points = the facet planes (exact).
std::vector<OffsetPlane> facet_planes(const std::vector<Vec3>& pts) {
  std::vector<Q3> q;
  for (const Vec3& p : pts) q.push_back(lemma_ref::exact(p));
  std::vector<OffsetPlane> planes;
  auto sub = [](const Q3& a, const Q3& b) { return Q3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  for (std::size_t i = 0; i < q.size(); ++i) {
    for (std::size_t j = i + 1; j < q.size(); ++j) {
      for (std::size_t k = j + 1; k < q.size(); ++k) {
        {  // Cheap floating-point rejection of triples with points clearly on both sides.
          const Vec3 nd = lemma_ref::cross(lemma_ref::sub(pts[j], pts[i]), lemma_ref::sub(pts[k], pts[i]));
          const double cd = lemma_ref::dot(nd, pts[i]);
          const double tol = 1e-6 * (1.0 + lemma_ref::norm(nd) * (1.0 + lemma_ref::norm(pts[i])));
          bool pos = false, neg = false;
          for (const Vec3& p : pts) {
            const double sd = lemma_ref::dot(nd, p) - cd;
            pos = pos || sd > tol;
            neg = neg || sd < -tol;
          }
          if (pos && neg) continue;
        }
        const Q3 u = sub(q[j], q[i]), v = sub(q[k], q[i]);
        Q3 n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
        const Q c = lemma_ref::dot_q(n, q[i]);
        bool below = true, above = true;
        for (const Q3& p : q) {
          const Q s = lemma_ref::dot_q(n, p);
          below = below && s <= c;
          above = above && s >= c;
        }
        if (above) {
          for (Q& x : n) x = -x;
          planes.push_back({n, -c});
        } else if (below) {
          planes.push_back({n, c});
        }
      }
    }
  }
  return planes;
}

TEST(LemmaOffsetContainment, RoundedSumAcceptedOnlyIfItContainsTheOffset) {
  std::mt19937 rng(303);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int accepted = 0, rejected = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const double delta = 0.1 + u01(rng);
    const auto h_pts = random_offset_points(rng, 4, {u01(rng), u01(rng), u01(rng)}, 1.0);
    // Even trials: cube slightly larger than delta (must be accepted); odd: slightly smaller.
    const double half_side = delta * (trial % 2 == 0 ? 1.0 + 1e-9 : 1.0 - 1e-9);
    std::vector<Vec3> rounded;  // vertices of H (+) cube, rounded to double by the additions
    for (const Vec3& h : h_pts)
      for (const Vec3& corner : kCubeCorners) rounded.push_back(lemma_ref::add(h, lemma_ref::scale(corner, half_side)));
    const auto planes = facet_planes(rounded);
    ASSERT_GE(planes.size(), 4u);
    const Q dq(delta);
    bool accept = true;
    const OffsetPlane* failing = nullptr;
    for (const OffsetPlane& f : planes) {
      Q max_h = lemma_ref::dot_q(f.n, lemma_ref::exact(h_pts[0]));
      for (const Vec3& h : h_pts) max_h = std::max(max_h, lemma_ref::dot_q(f.n, lemma_ref::exact(h)));
      const Q s = f.c - max_h;  // proofs/offset-containment.md#lemma-rounded-sum
      if (!(s >= 0 && s * s >= dq * dq * lemma_ref::dot_q(f.n, f.n))) {
        accept = false;
        failing = &f;
        break;
      }
    }
    EXPECT_EQ(accept, trial % 2 == 0) << "trial " << trial;
    if (accept) {
      ++accepted;
      // Points of H (+) B(0, delta) are inside every facet plane of R.
      for (int k = 0; k < 300; ++k) {
        const Vec3 b = ball_point(random_unit(rng), delta * (k % 2 == 0 ? 1.0 : u01(rng)), delta);
        const Q3 h = lemma_ref::exact(random_in_offset_hull(rng, h_pts));
        const Q3 x{h[0] + Q(b[0]), h[1] + Q(b[1]), h[2] + Q(b[2])};  // exact sum
        for (const OffsetPlane& f : planes) EXPECT_LE(lemma_ref::dot_q(f.n, x), f.c);
      }
    } else {
      ++rejected;
      // The rejection is justified: the offset point h* + b in the failing normal's direction
      // lies outside that facet plane.
      std::size_t best = 0;
      for (std::size_t k = 1; k < h_pts.size(); ++k)
        if (lemma_ref::dot_q(failing->n, lemma_ref::exact(h_pts[k])) >
            lemma_ref::dot_q(failing->n, lemma_ref::exact(h_pts[best])))
          best = k;
      const Vec3 nd{failing->n[0].convert_to<double>(), failing->n[1].convert_to<double>(),
                    failing->n[2].convert_to<double>()};
      const Vec3 b = ball_point(lemma_ref::scale(nd, 1.0 / lemma_ref::norm(nd)), delta, delta);
      const Q3 h = lemma_ref::exact(h_pts[best]);
      const Q3 x{h[0] + Q(b[0]), h[1] + Q(b[1]), h[2] + Q(b[2])};
      EXPECT_GT(lemma_ref::dot_q(failing->n, x), failing->c) << "trial " << trial;
    }
  }
  EXPECT_EQ(accepted, 6);
  EXPECT_EQ(rejected, 6);
}

}  // namespace
