#pragma once
/// \file
/// \brief Independent reference code for the lemma tests in tests/certify/: a tiny standard-DH
/// forward kinematics and exact rational helpers. Deliberately does not use the library's
/// kinematics or geometry, so the tests check the proofs' inequalities against a second
/// implementation.

#include <array>
#include <cmath>
#include <vector>

#include <boost/multiprecision/cpp_int.hpp>

namespace lemma_ref {

/// Exact rationals; construction from double is exact.
using Q = boost::multiprecision::cpp_rational;

using Vec3 = std::array<double, 3>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

/// One standard-DH joint: A = Rot_z(theta) Trans_z(d) Trans_x(a) Rot_x(alpha), with theta = theta0 + q
/// (revolute) or d = d0 + q (prismatic).
struct DhJoint {
  bool prismatic = false;
  double theta0 = 0.0, d0 = 0.0, a = 0.0, alpha = 0.0;
  double qmin = 0.0, qmax = 0.0;
};

/// Rigid transform as a 3x4 row-major matrix [R | t].
struct Frame {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
  Vec3 origin() const { return {m[0][3], m[1][3], m[2][3]}; }
  Vec3 z_axis() const { return {m[0][2], m[1][2], m[2][2]}; }
  Vec3 apply(const Vec3& p) const {
    Vec3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    return r;
  }
  Frame compose(const Frame& b) const {
    Frame c;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 4; ++j) {
        double s = (j == 3) ? m[i][3] : 0.0;
        for (int k = 0; k < 3; ++k) s += m[i][k] * b.m[k][j];
        c.m[i][j] = s;
      }
    }
    return c;
  }
};

inline Frame dh_transform(const DhJoint& j, double q) {
  const double theta = j.prismatic ? j.theta0 : j.theta0 + q;
  const double d = j.prismatic ? j.d0 + q : j.d0;
  const double ct = std::cos(theta), st = std::sin(theta);
  const double ca = std::cos(j.alpha), sa = std::sin(j.alpha);
  Frame f;
  const double m[3][4] = {{ct, -st * ca, st * sa, j.a * ct},
                          {st, ct * ca, -ct * sa, j.a * st},
                          {0.0, sa, ca, d}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) f.m[r][c] = m[r][c];
  return f;
}

/// Frames 0..N (frame 0 = world) of the chain at q.
inline std::vector<Frame> forward_frames(const std::vector<DhJoint>& chain, const std::vector<double>& q) {
  std::vector<Frame> frames(chain.size() + 1);
  for (std::size_t j = 0; j < chain.size(); ++j) frames[j + 1] = frames[j].compose(dh_transform(chain[j], q[j]));
  return frames;
}

/// Distance from p to the line through o with unit direction z.
inline double distance_to_axis(const Vec3& p, const Vec3& o, const Vec3& z) {
  const Vec3 w = sub(p, o);
  return norm(sub(w, scale(z, dot(w, z))));
}

inline std::array<Q, 3> exact(const Vec3& v) { return {Q(v[0]), Q(v[1]), Q(v[2])}; }
inline Q dot_q(const std::array<Q, 3>& a, const std::array<Q, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

}  // namespace lemma_ref
