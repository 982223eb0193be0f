/// \file
/// \brief Independent exact references (the only CGAL test translation unit).

#include "support/geometry_reference.hpp"

#include <CGAL/Cartesian.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/Homogeneous.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polytope_distance_d.h>
#include <CGAL/Polytope_distance_d_traits_3.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace grpvss::testing {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using EpeckMesh = CGAL::Surface_mesh<Epeck::Point_3>;
using EpickMesh = CGAL::Surface_mesh<Epick::Point_3>;
using QK = CGAL::Cartesian<CGAL::Gmpq>;
using DistTraits = CGAL::Polytope_distance_d_traits_3<QK>;
using Distance = CGAL::Polytope_distance_d<DistTraits>;
using Z = CGAL::Gmpzf;

template <class Mesh>
Mesh hull_mesh(const Points& pts) {
  using P = typename boost::property_traits<
      typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type;
  std::vector<P> q;
  for (const auto& p : pts) q.emplace_back(p.x(), p.y(), p.z());
  Mesh mesh;
  CGAL::convex_hull_3(q.begin(), q.end(), mesh);
  return mesh;
}

struct Plane {
  std::array<Z, 3> n;
  Z c;
};

/// Planes n.x <= c of all hull triangles (Epick hull, exact normals in Gmpzf).
std::vector<Plane> hull_planes(const Points& pts) {
  const EpickMesh mesh = hull_mesh<EpickMesh>(pts);
  std::vector<Plane> planes;
  for (auto f : mesh.faces()) {
    std::vector<Epick::Point_3> v;
    for (auto vd : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) v.push_back(mesh.point(vd));
    const Z ux = Z(v[1].x()) - Z(v[0].x()), uy = Z(v[1].y()) - Z(v[0].y()),
            uz = Z(v[1].z()) - Z(v[0].z());
    const Z wx = Z(v[2].x()) - Z(v[0].x()), wy = Z(v[2].y()) - Z(v[0].y()),
            wz = Z(v[2].z()) - Z(v[0].z());
    Plane pl;
    pl.n = {uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx};
    pl.c = pl.n[0] * Z(v[0].x()) + pl.n[1] * Z(v[0].y()) + pl.n[2] * Z(v[0].z());
    planes.push_back(pl);
  }
  return planes;
}

std::vector<QK::Point_3> q_points(const Points& pts) {
  std::vector<QK::Point_3> out;
  for (const auto& p : pts) out.emplace_back(CGAL::Gmpq(p.x()), CGAL::Gmpq(p.y()), CGAL::Gmpq(p.z()));
  return out;
}

}  // namespace

geometry::Contact reference_contact(const Points& a, const Points& b) {
  const EpeckMesh ma = hull_mesh<EpeckMesh>(a);
  const EpeckMesh mb = hull_mesh<EpeckMesh>(b);
  const bool meet = CGAL::Polygon_mesh_processing::do_intersect(
      ma, mb, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
      CGAL::parameters::do_overlap_test_of_bounded_sides(true));
  if (!meet) return geometry::Contact::kSeparated;

  // Interior overlap LP over variables (x, y, z, t).
  using Program = CGAL::Quadratic_program<Z>;
  Program lp(CGAL::SMALLER, false, 0, false, 0);
  int row = 0;
  for (const Points* set : {&a, &b}) {
    for (const Plane& pl : hull_planes(*set)) {
      for (int j = 0; j < 3; ++j) lp.set_a(j, row, pl.n[j]);
      lp.set_a(3, row, Z(1));
      lp.set_b(row, pl.c);
      ++row;
    }
  }
  lp.set_u(3, true, Z(1));
  lp.set_c(3, Z(-1));
  const auto solution = CGAL::solve_linear_program(lp, Z());
  if (!solution.is_optimal()) throw std::logic_error("reference LP not optimal");
  return CGAL::is_negative(solution.objective_value()) ? geometry::Contact::kOverlapping
                                                       : geometry::Contact::kTouching;
}

bool reference_distance_squared_at_least(const Points& a, const Points& b, double x) {
  const auto qa = q_points(a);
  const auto qb = q_points(b);
  const Distance d(qa.begin(), qa.end(), qb.begin(), qb.end());
  const CGAL::Gmpq dist2 = d.squared_distance_numerator() / d.squared_distance_denominator();
  return dist2 >= CGAL::Gmpq(x);
}

int double_nt_distance_squared_vs_exact(const Points& a, const Points& b) {
  // cgal-notes.md's configuration has NT = double for the solver's pricing; ET here is Gmpzf
  // (instead of MP_Float) so that the result converts to Gmpq exactly.
  using HK = CGAL::Homogeneous<double>;
  using Traits = CGAL::Polytope_distance_d_traits_3<HK, Z, double>;
  std::vector<HK::Point_3> ha, hb;
  for (const auto& p : a) ha.emplace_back(p.x(), p.y(), p.z(), 1.0);
  for (const auto& p : b) hb.emplace_back(p.x(), p.y(), p.z(), 1.0);
  const CGAL::Polytope_distance_d<Traits> fast(ha.begin(), ha.end(), hb.begin(), hb.end());
  auto to_gmpq = [](const Z& x) {  // m * 2^e, exactly
    CGAL::Gmpq q(x.man());
    if (x.exp() >= 0) {
      mpq_mul_2exp(q.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(x.exp()));
    } else {
      mpq_div_2exp(q.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-x.exp()));
    }
    return q;
  };
  const CGAL::Gmpq f =
      to_gmpq(fast.squared_distance_numerator()) / to_gmpq(fast.squared_distance_denominator());
  const auto qa = q_points(a);
  const auto qb = q_points(b);
  const Distance exact(qa.begin(), qa.end(), qb.begin(), qb.end());
  const CGAL::Gmpq e = exact.squared_distance_numerator() / exact.squared_distance_denominator();
  return f > e ? 1 : f < e ? -1 : 0;
}

double reference_distance(const Points& a, const Points& b) {
  const auto qa = q_points(a);
  const auto qb = q_points(b);
  const Distance d(qa.begin(), qa.end(), qb.begin(), qb.end());
  return std::sqrt(CGAL::to_double(d.squared_distance_numerator() /
                                   d.squared_distance_denominator()));
}

void reference_closest_points(const Points& a, const Points& b, Eigen::Vector3d& p,
                              Eigen::Vector3d& q) {
  const auto qa = q_points(a);
  const auto qb = q_points(b);
  const Distance d(qa.begin(), qa.end(), qb.begin(), qb.end());
  std::vector<CGAL::Gmpq> pc(d.realizing_point_p_coordinates_begin(),
                             d.realizing_point_p_coordinates_end());
  std::vector<CGAL::Gmpq> qc(d.realizing_point_q_coordinates_begin(),
                             d.realizing_point_q_coordinates_end());
  for (int k = 0; k < 3; ++k) {
    p[k] = CGAL::to_double(pc[k] / pc[3]);
    q[k] = CGAL::to_double(qc[k] / qc[3]);
  }
}

int orientation_sign(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                     const Eigen::Vector3d& r, const Eigen::Vector3d& s) {
  // CGAL::orientation is the sign of det(q - p, r - p, s - p).
  const auto o = CGAL::orientation(Epick::Point_3(p.x(), p.y(), p.z()),
                                   Epick::Point_3(q.x(), q.y(), q.z()),
                                   Epick::Point_3(r.x(), r.y(), r.z()),
                                   Epick::Point_3(s.x(), s.y(), s.z()));
  return o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0;
}

bool point_in_hull_exactly(const Points& pts, const Eigen::Vector3d& x) {
  for (const Plane& pl : hull_planes(pts)) {
    if (pl.n[0] * Z(x.x()) + pl.n[1] * Z(x.y()) + pl.n[2] * Z(x.z()) > pl.c) return false;
  }
  return true;
}

int count_points_outside_hull_exactly(const Points& pts, const Points& xs) {
  const std::vector<Plane> planes = hull_planes(pts);
  int outside = 0;
  for (const auto& x : xs) {
    for (const Plane& pl : planes) {
      if (pl.n[0] * Z(x.x()) + pl.n[1] * Z(x.y()) + pl.n[2] * Z(x.z()) > pl.c) {
        ++outside;
        break;
      }
    }
  }
  return outside;
}

bool reference_contains_ball_sum(const Points& outer, const Points& inner, double radius) {
  const Z r(radius);
  for (const Plane& pl : hull_planes(outer)) {
    Z max_h = pl.n[0] * Z(inner[0].x()) + pl.n[1] * Z(inner[0].y()) + pl.n[2] * Z(inner[0].z());
    for (const auto& h : inner) {
      const Z d = pl.n[0] * Z(h.x()) + pl.n[1] * Z(h.y()) + pl.n[2] * Z(h.z());
      if (d > max_h) max_h = d;
    }
    const Z g = pl.c - max_h;
    if (CGAL::sign(g) == CGAL::NEGATIVE) return false;
    if (g * g < r * r * (pl.n[0] * pl.n[0] + pl.n[1] * pl.n[1] + pl.n[2] * pl.n[2])) return false;
  }
  return true;
}

std::vector<Points> ibm7545_hulls() {
  std::vector<Points> hulls;
  Points current;
  for (const char* name : {"robot.txt", "environment.txt"}) {
    std::ifstream in(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/" + name);
    if (!in) throw std::runtime_error(std::string("cannot open ") + name);
    std::string line;
    while (std::getline(in, line)) {
      std::stringstream ss(line);
      std::string field;
      std::vector<double> values;
      while (std::getline(ss, field, ',')) values.push_back(std::stod(field));
      if (values.size() != 3) continue;
      current.emplace_back(values[0], values[1], values[2]);
      if (current.size() == 16) {
        hulls.push_back(current);
        current.clear();
      }
    }
  }
  return hulls;
}

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  return q.toRotationMatrix();
}

Points transformed(const Points& pts, const Eigen::Matrix3d& R, const Eigen::Vector3d& t) {
  Points out;
  for (const auto& p : pts) out.push_back(R * p + t);
  return out;
}

Points box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Points out;
  for (int i = 0; i < 8; ++i) {
    out.emplace_back((i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(),
                     (i & 4) ? hi.z() : lo.z());
  }
  return out;
}

}  // namespace grpvss::testing
