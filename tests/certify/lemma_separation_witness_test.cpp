// Checks proofs/separation-witness.md: a verified witness (n, a0, b0) and the directed-rounding
// centroid-sphere cull never claim more distance than there is.

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::Q;
using lemma_ref::Vec3;

std::vector<Vec3> random_witness_points(std::mt19937& rng, int count, const Vec3& centre, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (int k = 0; k < count; ++k)
    pts.push_back(lemma_ref::add(centre, {spread * u(rng), spread * u(rng), spread * u(rng)}));
  return pts;
}

Vec3 random_in_witness_hull(std::mt19937& rng, const std::vector<Vec3>& pts) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<double> w(pts.size());
  double sum = 0.0;
  for (double& x : w) sum += (x = u01(rng) * u01(rng) * u01(rng));
  Vec3 p{0, 0, 0};
  for (std::size_t k = 0; k < pts.size(); ++k) p = lemma_ref::add(p, lemma_ref::scale(pts[k], w[k] / sum));
  return p;
}

double sampled_distance(std::mt19937& rng, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double best = 1e300;
  for (const Vec3& x : a)
    for (const Vec3& y : b) best = std::min(best, lemma_ref::norm(lemma_ref::sub(x, y)));
  for (int k = 0; k < 1000; ++k)
    best = std::min(best, lemma_ref::norm(lemma_ref::sub(random_in_witness_hull(rng, a), random_in_witness_hull(rng, b))));
  return best;
}

// Lower bound (b0 - a0)/|n| of a witness verified exactly; returns -1 if (n, a0, b0) is no witness.
double witness_bound(const Vec3& n, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const auto nq = lemma_ref::exact(n);
  Q a0 = lemma_ref::dot_q(nq, lemma_ref::exact(a[0])), b0 = lemma_ref::dot_q(nq, lemma_ref::exact(b[0]));
  for (const Vec3& x : a) a0 = std::max(a0, lemma_ref::dot_q(nq, lemma_ref::exact(x)));
  for (const Vec3& y : b) b0 = std::min(b0, lemma_ref::dot_q(nq, lemma_ref::exact(y)));
  if (!(b0 > a0)) return -1.0;
  double c = (b0 - a0).convert_to<double>() / lemma_ref::norm(n);
  // proofs/separation-witness.md#lemma-witness, exact use: c^2 |n|^2 <= (b0 - a0)^2.
  while (Q(c) * Q(c) * lemma_ref::dot_q(nq, nq) > (b0 - a0) * (b0 - a0)) c = std::nextafter(c, 0.0);
  return c;
}

TEST(LemmaSeparationWitness, WitnessLowerBoundNeverExceedsSampledDistance) {
  std::mt19937 rng(404);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int witnesses = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto a = random_witness_points(rng, 3 + trial % 6, {0, 0, 0}, 1.0);
    const Vec3 centre{2.5 * u(rng), 2.5 * u(rng), 2.5 * u(rng)};
    const auto b = random_witness_points(rng, 3 + trial % 5, centre, 1.0);
    const Vec3 n = lemma_ref::add(centre, {0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng)});
    const double bound = witness_bound(n, a, b);
    if (bound < 0.0) continue;
    ++witnesses;
    EXPECT_LE(bound, sampled_distance(rng, a, b) + 1e-12) << "trial " << trial;
  }
  EXPECT_GT(witnesses, 100);
  // Tightness: two single points with n along their difference give their distance.
  const std::vector<Vec3> a{{0.1, 0.2, 0.3}}, b{{1.1, 2.2, -0.7}};
  const double d = lemma_ref::norm(lemma_ref::sub(b[0], a[0]));
  EXPECT_NEAR(witness_bound(lemma_ref::sub(b[0], a[0]), a, b), d, 1e-14);
  EXPECT_LE(witness_bound(lemma_ref::sub(b[0], a[0]), a, b), d);
}

// |x - y| for doubles, rounded in the current mode without sign trouble (larger minus smaller).
double abs_diff(double x, double y) { return std::max(x, y) - std::min(x, y); }

double distance_in_mode(const Vec3& p, const Vec3& q, int mode) {
  const int old = std::fegetround();
  std::fesetround(mode);
  const double dx = abs_diff(p[0], q[0]), dy = abs_diff(p[1], q[1]), dz = abs_diff(p[2], q[2]);
  const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
  std::fesetround(old);
  return r;
}

struct Sphere {
  Vec3 centre;
  double radius_up;
};

Sphere bounding_sphere_up(const std::vector<Vec3>& pts) {
  Vec3 c{0, 0, 0};
  for (const Vec3& p : pts) c = lemma_ref::add(c, p);
  c = lemma_ref::scale(c, 1.0 / pts.size());  // any centre works; rounding here is harmless
  double r = 0.0;
  for (const Vec3& p : pts) r = std::max(r, distance_in_mode(p, c, FE_UPWARD));
  return {c, r};
}

// proofs/separation-witness.md#lemma-sphere-cull with #directed-rounding.
double sphere_cull_bound(const Sphere& sa, const Sphere& sb) {
  const double centres = distance_in_mode(sa.centre, sb.centre, FE_DOWNWARD);
  const int old = std::fegetround();
  std::fesetround(FE_DOWNWARD);
  const double lambda = centres - sa.radius_up - sb.radius_up;
  std::fesetround(old);
  return lambda;
}

TEST(LemmaSeparationWitness, SphereCullLowerBoundNeverExceedsSampledDistance) {
  std::mt19937 rng(505);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int positive = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto a = random_witness_points(rng, 4 + trial % 8, {0, 0, 0}, 1.0);
    const auto b = random_witness_points(rng, 4 + trial % 5, {4.0 * u(rng), 4.0 * u(rng), 4.0 * u(rng)}, 1.0);
    const double lambda = sphere_cull_bound(bounding_sphere_up(a), bounding_sphere_up(b));
    if (lambda > 0.0) ++positive;
    EXPECT_LE(lambda, sampled_distance(rng, a, b) + 1e-12) << "trial " << trial;
  }
  EXPECT_GT(positive, 50);
}

TEST(LemmaSeparationWitness, DirectedRoundingBracketsTheExactRadius) {
  std::mt19937 rng(606);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int nearest_too_small = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 p{u(rng), u(rng), u(rng)}, c{u(rng) * 1e-3, u(rng), u(rng) * 1e3};
    Q exact_sq = 0;
    for (int k = 0; k < 3; ++k) exact_sq += (Q(p[k]) - Q(c[k])) * (Q(p[k]) - Q(c[k]));
    const double up = distance_in_mode(p, c, FE_UPWARD);
    const double down = distance_in_mode(p, c, FE_DOWNWARD);
    const double nearest = distance_in_mode(p, c, FE_TONEAREST);
    EXPECT_GE(Q(up) * Q(up), exact_sq) << "trial " << trial;
    EXPECT_GE(down, 0.0);
    EXPECT_LE(Q(down) * Q(down), exact_sq) << "trial " << trial;
    if (Q(nearest) * Q(nearest) < exact_sq) ++nearest_too_small;
  }
  // Round-to-nearest under-estimates the radius in many cases: the cull needs directed rounding.
  EXPECT_GT(nearest_too_small, 100);
}

}  // namespace
