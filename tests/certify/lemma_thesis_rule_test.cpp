// Checks proofs/thesis-rule.md: the concrete counterexamples to "clear at every step => clear
// motion" for the thesis rule max{min[2D/cos(theta/2), 2D + L], Dmin} applied at link-frame
// origins (IBM 7545 kinematics, independent reference FK), the straight-line counterexample at a
// sharp vertex, and the cone lemma that does hold.

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"

namespace {

using lemma_ref::DhJoint;
using lemma_ref::Vec3;

constexpr double kDeg = M_PI / 180.0;

// IBM 7545 of Appendix A.1.1.1 (standard DH, radians, inches).
std::vector<DhJoint> ibm7545() {
  DhJoint j1, j2, j3, j4;
  j1.d0 = 25.5;
  j1.a = 15.8;
  j2.a = 9.8;
  j2.alpha = M_PI;
  j3.prismatic = true;
  j4.d0 = 15.05;
  return {j1, j2, j3, j4};
}

double thesis_allowance(double delta, double theta, double thickness, double d_min) {
  return std::max(std::min(2.0 * delta / std::cos(theta / 2.0), 2.0 * delta + thickness), d_min);
}

std::vector<Vec3> box_vertices(const Vec3& centre, const std::array<Vec3, 3>& axes, const Vec3& half) {
  std::vector<Vec3> v;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) {
        Vec3 p = centre;
        p = lemma_ref::add(p, lemma_ref::scale(axes[0], sx * half[0]));
        p = lemma_ref::add(p, lemma_ref::scale(axes[1], sy * half[1]));
        p = lemma_ref::add(p, lemma_ref::scale(axes[2], sz * half[2]));
        v.push_back(p);
      }
  return v;
}

// Gap along world direction n between point sets (min over b minus max over a), n unit.
double gap_along(const Vec3& n, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double amax = -1e300, bmin = 1e300;
  for (const Vec3& p : a) amax = std::max(amax, lemma_ref::dot(n, p));
  for (const Vec3& p : b) bmin = std::min(bmin, lemma_ref::dot(n, p));
  return bmin - amax;
}

double l1(const Vec3& v) { return std::abs(v[0]) + std::abs(v[1]) + std::abs(v[2]); }

std::vector<Vec3> place(const lemma_ref::Frame& f, const std::vector<Vec3>& pts) {
  std::vector<Vec3> out;
  for (const Vec3& p : pts) out.push_back(f.apply(p));
  return out;
}

// Rotation part of a frame applied to a direction.
Vec3 rotate(const lemma_ref::Frame& f, const Vec3& d) {
  return lemma_ref::sub(f.apply(d), f.origin());
}

TEST(LemmaThesisRule, Ibm7545ToolSweepsThroughPlateWhileOriginsStayPut) {
  const auto chain = ibm7545();
  const double delta = 0.5, thickness = 1.0, theta = 90.0 * kDeg;
  const std::vector<double> q_start{0, 0, 0, 0}, q_end{0, 0, 0, 30.0 * kDeg};
  const auto f_start = lemma_ref::forward_frames(chain, q_start);
  const auto f_end = lemma_ref::forward_frames(chain, q_end);
  // Home puts the end effector at (25.6, 0, 10.45) (thesis-notes.md).
  EXPECT_NEAR(f_start[4].origin()[0], 25.6, 1e-12);
  EXPECT_NEAR(f_start[4].origin()[2], 10.45, 1e-12);

  // Tool on link 4: x_L in [0,10], y_L in [-0.25,0.25], z_L in [-7.5,-7].
  const std::array<Vec3, 3> link_axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  const auto tool_L = box_vertices({5.0, 0.0, -7.25}, link_axes, {5.0, 0.25, 0.25});
  // Plate (thickness L = 1), given in link-4 coordinates at home, placed in the world.
  const double c15 = std::cos(15 * kDeg), s15 = std::sin(15 * kDeg);
  const auto plate_L = box_vertices({8 * c15, 8 * s15, -7.25}, {{{c15, s15, 0}, {-s15, c15, 0}, {0, 0, 1}}},
                                    {2.0, 0.5 * thickness, 1.0});
  const auto plate_W = place(f_start[4], plate_L);

  // 1. Every link-frame origin stays put: the thesis rule accepts the move as one step.
  double d_min_start = 0.0;
  for (int i = 0; i <= 4; ++i) {
    const double moved = lemma_ref::norm(lemma_ref::sub(f_end[i].origin(), f_start[i].origin()));
    EXPECT_LE(moved, 1e-12) << "origin " << i;
  }
  // 2. Both step ends are clear, with margin, for a cube expansion of half-side delta.
  for (int end = 0; end < 2; ++end) {
    const auto& frames = end == 0 ? f_start : f_end;
    const Vec3 n_W = rotate(frames[4], {0, end == 0 ? 1.0 : -1.0, 0});  // tool's side facing the plate
    const double gap = gap_along(n_W, place(frames[4], tool_L), plate_W);
    EXPECT_NEAR(gap, 6 * s15 - 0.5 * c15 - 0.25, 1e-9);  // 0.8199
    EXPECT_GT(gap - delta * l1(n_W), 0.1);                // world-aligned expansion cube
    EXPECT_GT(gap - delta * 1.0, 0.1);                    // link-aligned expansion cube
    if (end == 0) d_min_start = gap;
  }
  const double allowance = thesis_allowance(delta, theta, thickness, d_min_start);
  EXPECT_NEAR(allowance, std::sqrt(2.0), 1e-12);
  // 3. The tool tip moves far more than 2D + L (and than the allowance).
  const Vec3 tip_L{10, 0, -7.25};
  const double chord = lemma_ref::norm(lemma_ref::sub(f_end[4].apply(tip_L), f_start[4].apply(tip_L)));
  EXPECT_NEAR(chord, 20 * s15, 1e-9);  // 5.176
  EXPECT_GT(chord, 2 * delta + thickness);
  EXPECT_GT(chord, allowance);
  // 4. Mid-way (q4 = 15 deg) the tool point (8,0,-7.25) is the plate's centre: collision.
  const auto f_mid = lemma_ref::forward_frames(chain, {0, 0, 0, 15.0 * kDeg});
  const Vec3 tool_point = f_mid[4].apply({8, 0, -7.25});
  const Vec3 plate_centre = f_start[4].apply({8 * c15, 8 * s15, -7.25});
  EXPECT_LE(lemma_ref::norm(lemma_ref::sub(tool_point, plate_centre)), 1e-9);
  // ...and it is inside every face of the plate with margin (half thickness 0.5).
  const Vec3 tangential_W = rotate(f_start[4], {-s15, c15, 0});
  EXPECT_LT(std::abs(lemma_ref::dot(lemma_ref::sub(tool_point, plate_centre), tangential_W)), 0.5 - 0.4);
}

TEST(LemmaThesisRule, Ibm7545Link4OctagonSweepsThroughThinCube) {
  const auto chain = ibm7545();
  const double delta = 0.01, thickness = 0.01, theta = 90.0 * kDeg;
  // Link-4 hull of the sample robot file (data/ibm7545/robot.txt, last hull).
  std::vector<Vec3> hull_L;
  for (double z : {0.0, -7.0})
    for (const auto& xy : std::vector<std::array<double, 2>>{
             {0.35, -0.35}, {0, -0.5}, {-0.35, -0.35}, {-0.5, 0}, {-0.35, 0.35}, {0, 0.5}, {0.35, 0.35}, {0.5, 0}})
      hull_L.push_back({xy[0], xy[1], z});
  const double c = std::cos(22.5 * kDeg), s = std::sin(22.5 * kDeg);
  const Vec3 u{c, s, 0};
  const auto f_start = lemma_ref::forward_frames(chain, {0, 0, 0, 0});
  const auto f_end = lemma_ref::forward_frames(chain, {0, 0, 0, 90.0 * kDeg});
  const auto cube_W = place(f_start[4], box_vertices({0.49 * c, 0.49 * s, -3.5}, {{u, {-s, c, 0}, {0, 0, 1}}},
                                                      {0.005, 0.005, 0.005}));
  const Vec3 n_W = rotate(f_start[4], u);
  for (int i = 0; i <= 4; ++i)
    EXPECT_LE(lemma_ref::norm(lemma_ref::sub(f_end[i].origin(), f_start[i].origin())), 1e-12);
  double d_min_start = 0.0;
  for (int end = 0; end < 2; ++end) {
    const double gap = gap_along(n_W, place(end == 0 ? f_start[4] : f_end[4], hull_L), cube_W);
    EXPECT_NEAR(gap, 0.485 - 0.5 * c, 1e-9);  // 0.0231
    EXPECT_GT(gap - delta * l1(n_W), 0.009);   // expansion cube support 0.0131
    EXPECT_GT(gap - delta * (c + s), 0.009);
    if (end == 0) d_min_start = gap;
  }
  const double allowance = thesis_allowance(delta, theta, thickness, d_min_start);
  EXPECT_NEAR(allowance, 0.02 * std::sqrt(2.0), 1e-12);
  EXPECT_GT(0.5 * M_PI / 2, 20 * allowance);  // the vertex arc (0.785) dwarfs the allowance
  // At q4 = 22.5 deg the hull contains 0.98 of the way from the axis to the vertex (0.5,0,-3.5),
  // which is the obstacle's centre.
  const auto f_mid = lemma_ref::forward_frames(chain, {0, 0, 0, 22.5 * kDeg});
  const Vec3 axis_point = f_mid[4].apply({0, 0, -3.5});     // midpoint of opposite hull vertices
  const Vec3 vertex_point = f_mid[4].apply({0.5, 0, -3.5});  // midpoint of a vertical hull edge
  const Vec3 x = lemma_ref::add(axis_point, lemma_ref::scale(lemma_ref::sub(vertex_point, axis_point), 0.98));
  EXPECT_LE(lemma_ref::norm(lemma_ref::sub(x, f_start[4].apply({0.49 * c, 0.49 * s, -3.5}))), 1e-9);
}

TEST(LemmaThesisRule, StraightPointPassesSharpPyramidVertex) {
  const double delta = 1.0, k = 0.1;
  // Pyramid {|x| <= k(z+0.1), |y| <= k(z+0.1), z <= 100}: outward normals and offsets n.x <= c.
  struct Face {
    Vec3 n;
    double c;
  };
  const std::vector<Face> faces{{{1, 0, -k}, 0.1 * k}, {{-1, 0, -k}, 0.1 * k}, {{0, 1, -k}, 0.1 * k},
                                {{0, -1, -k}, 0.1 * k}, {{0, 0, 1}, 100.0}};
  // Smallest interior dihedral angle over adjacent faces: pi - angle between outward normals.
  double theta = M_PI;
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (std::size_t j = i + 1; j < faces.size(); ++j) {
      const double cosang = lemma_ref::dot(faces[i].n, faces[j].n) /
                            (lemma_ref::norm(faces[i].n) * lemma_ref::norm(faces[j].n));
      if (cosang < -0.5) continue;  // opposite side faces do not meet
      theta = std::min(theta, M_PI - std::acos(cosang));
    }
  EXPECT_NEAR(theta / kDeg, std::atan(1 / k) / kDeg, 1e-9);  // 84.29 deg
  const double base_half_width = k * 100.1;
  const double thickness = 2 * base_half_width;  // 20.02
  const double allowance = thesis_allowance(delta, theta, thickness, 0.0);
  EXPECT_NEAR(allowance, 2 * delta / std::cos(theta / 2), 1e-12);  // 2.697
  const Vec3 x0{-1.25, 0, 0}, x1{1.25, 0, 0};
  EXPECT_LE(lemma_ref::norm(lemma_ref::sub(x1, x0)), allowance);
  // Both ends: the expansion cube of half-side delta lies outside one face plane (separated).
  for (const Vec3& x : {x0, x1}) {
    bool separated = false;
    for (const Face& f : faces) {
      const double min_over_cube = lemma_ref::dot(f.n, x) - delta * l1(f.n) - f.c;
      separated = separated || min_over_cube > 0.1;
    }
    EXPECT_TRUE(separated);
  }
  // The segment's midpoint is interior to the pyramid.
  const Vec3 mid{0, 0, 0};
  for (const Face& f : faces) EXPECT_LT(lemma_ref::dot(f.n, mid), f.c);
  // Lemma 1 with the vertex cone's own half-angle atan(k) does predict detection only below 2.010.
  EXPECT_LT(2 * delta / std::cos(std::atan(k)), 2.5);
}

// Distance from x to the circular cone {y : angle(y, w) <= alpha} (apex 0, unit w).
double cone_distance(const Vec3& x, const Vec3& w, double alpha) {
  const double r = lemma_ref::norm(x);
  if (r == 0.0) return 0.0;
  const double phi = std::acos(std::clamp(lemma_ref::dot(x, w) / r, -1.0, 1.0));
  if (phi <= alpha) return 0.0;
  if (phi - alpha < M_PI / 2) return r * std::sin(phi - alpha);
  return r;
}

TEST(LemmaThesisRule, StraightSegmentConeLemmaOnRandomWedges) {
  std::mt19937 rng(808);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  auto unit = [&] {
    Vec3 v{g(rng), g(rng), g(rng)};
    return lemma_ref::scale(v, 1.0 / lemma_ref::norm(v));
  };
  const double delta = 1.0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double alpha = 0.02 + 1.5 * u01(rng);
    const Vec3 w = unit(), u = unit();
    const double bound = 2 * delta / std::cos(alpha);
    const double len = bound * (1.0 - 1e-9) * u01(rng);
    const double a = len * u01(rng);
    const Vec3 x0 = lemma_ref::scale(u, -a), x1 = lemma_ref::scale(u, len - a);
    EXPECT_LT(std::min(cone_distance(x0, w, alpha), cone_distance(x1, w, alpha)), delta) << "trial " << trial;
  }
  // Tightness: just above the bound, the symmetric crossing perpendicular to the axis escapes.
  for (double alpha : {0.1, 0.5, 1.0, 1.4}) {
    const double len = 2 * delta / std::cos(alpha) * (1.0 + 1e-6);
    const Vec3 w{0, 0, 1}, x0{-len / 2, 0, 0}, x1{len / 2, 0, 0};
    EXPECT_GE(cone_distance(x0, w, alpha), delta);
    EXPECT_GE(cone_distance(x1, w, alpha), delta);
  }
}

// proofs/thesis-rule.md#lemma-dmin: on a circular arc of angle <= pi every point is within chord
// distance of the start (so a chord <= D_min keeps the whole arc in the closed D_min ball); for
// angles above pi it is not.
TEST(LemmaThesisRule, DminBallContainsArcsUpToHalfTurn) {
  std::mt19937 rng(909);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double radius = 0.1 + 10 * u01(rng), angle = M_PI * u01(rng);
    const Vec3 start{radius, 0, 0};
    const double chord = 2 * radius * std::sin(angle / 2);
    for (int k = 0; k <= 200; ++k) {
      const double a = angle * k / 200;
      const Vec3 p{radius * std::cos(a), radius * std::sin(a), 0};
      EXPECT_LE(lemma_ref::norm(lemma_ref::sub(p, start)), chord * (1 + 1e-12) + 1e-12) << "trial " << trial;
    }
  }
  // A 270 degree turn: chord = sqrt(2) R, but the half-turn point is 2R from the start.
  const double radius = 1.0, angle = 1.5 * M_PI;
  const double chord = 2 * radius * std::sin(angle / 2);
  const Vec3 half_turn{-radius, 0, 0}, start{radius, 0, 0};
  EXPECT_GT(lemma_ref::norm(lemma_ref::sub(half_turn, start)), chord + 0.5);
}

}  // namespace
