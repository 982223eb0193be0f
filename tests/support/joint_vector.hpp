#pragma once
// A joint vector written inline, `vector({0.1, -0.2})`, for the trajectory reader tests;
// defined once so that the tests' unity batches hold one definition.

#include <initializer_list>

#include <Eigen/Core>

namespace grpvss::test {

inline Eigen::VectorXd vector(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (const double x : values) v[i++] = x;
  return v;
}

}  // namespace grpvss::test
