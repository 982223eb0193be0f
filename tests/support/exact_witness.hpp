#pragma once
/// \file
/// \brief A separation witness decided in rationals, as the checker decides a recorded one.

#include <vector>

#include <Eigen/Core>

#include "grpvss/geometry/separation_witness.hpp"

namespace grpvss::test {

/// n.x <= o_a for every x of `below`, n.y >= o_b for every y of `above`, and o_a < o_b, each
/// decided in rationals (gmpxx).
bool witness_holds_exactly(const geometry::SeparationWitness& witness,
                           const std::vector<Eigen::Vector3d>& below,
                           const std::vector<Eigen::Vector3d>& above);

}  // namespace grpvss::test
