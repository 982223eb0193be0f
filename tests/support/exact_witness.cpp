#include "support/exact_witness.hpp"

#include <gmpxx.h>

namespace grpvss::test {

bool witness_holds_exactly(const geometry::SeparationWitness& witness,
                           const std::vector<Eigen::Vector3d>& below,
                           const std::vector<Eigen::Vector3d>& above) {
  const auto dot = [&](const Eigen::Vector3d& p) -> mpq_class {  // not an expression template
    return mpq_class(witness.normal.x()) * mpq_class(p.x()) + mpq_class(witness.normal.y()) * mpq_class(p.y()) +
           mpq_class(witness.normal.z()) * mpq_class(p.z());
  };
  for (const Eigen::Vector3d& x : below) {
    if (dot(x) > mpq_class(witness.offset_a)) return false;
  }
  for (const Eigen::Vector3d& y : above) {
    if (dot(y) < mpq_class(witness.offset_b)) return false;
  }
  return mpq_class(witness.offset_a) < mpq_class(witness.offset_b);
}

}  // namespace grpvss::test
