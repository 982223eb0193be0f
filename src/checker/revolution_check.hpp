#pragma once
// The checker's exact decisions about the revolution route of a self pair
// (proofs/two-ball-cover.md#revolution-route): that a hull's solid of revolution about the next
// joint's axis contains it with the margin for the axis's and the hull's errors, and that a
// witness's normal keeps the placed solid at the claimed distance from the other hull's side of
// the slab.

#include <vector>

#include <Eigen/Geometry>

#include "grpvss/geometry/revolution_solid.hpp"
#include "grpvss/geometry/separation_witness.hpp"

namespace grpvss::certify {

/// \brief Exactly: the solid is about the stored axis (same point, same direction, an exact
/// unit vector), its rings have strictly increasing axial coordinates, radii >= 0 and a concave
/// interpolation F, and
/// every vertex h of `raw_L`, with s = (h - p).u and r its distance from the axis, has
/// [s - mu, s + mu] within [s_1, s_k] and r + mu <= F on that interval (F the rings'
/// interpolation), mu = e_h + 2 (e_t + 4 e_r Lambda), Lambda = max radius + max |axial|.
/// proof: proofs/two-ball-cover.md#revolution-solid
bool solid_encloses_exactly(const geometry::RevolutionSolid& solid,
                            const std::vector<Eigen::Vector3d>& raw_L,
                            const geometry::JointAxisLine_L& axis, double hull_point_error);

/// \brief Exactly: every point x of the solid's image under X_WL (exact affine image) has
/// n.x + lambda |n| <= offset_b, for the witness's normal n and offset_b.
/// proof: proofs/two-ball-cover.md#revolution-solid-support
bool solid_side_holds_exactly(const geometry::RevolutionSolid& solid, const Eigen::Isometry3d& X_WL,
                              const geometry::SeparationWitness& witness, double lambda);

}  // namespace grpvss::certify
