#include "support/exact_hull_lp.hpp"

#include <stdexcept>

#include <boost/multiprecision/gmp.hpp>

namespace grpvss::test {
namespace {

using Rational = boost::multiprecision::mpq_rational;

}  // namespace

bool hulls_intersect_exact_lp(const std::vector<Eigen::Vector3d>& a,
                              const std::vector<Eigen::Vector3d>& b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("hulls_intersect_exact_lp: empty point set");
  const int m = static_cast<int>(a.size());
  const int n = static_cast<int>(b.size());
  constexpr int kRows = 5;  // x, y, z balance; sum lambda = 1; sum mu = 1
  const int columns = m + n + kRows;  // original variables, then one artificial per row
  const int rhs = columns;
  // Tableau rows 0..4 (constraints) and row 5 (reduced costs of phase 1, objective in rhs).
  std::vector<std::vector<Rational>> T(kRows + 1, std::vector<Rational>(columns + 1));
  for (int i = 0; i < m; ++i) {
    for (int r = 0; r < 3; ++r) T[r][i] = Rational(a[i][r]);  // double -> rational is exact
    T[3][i] = 1;
  }
  for (int j = 0; j < n; ++j) {
    for (int r = 0; r < 3; ++r) T[r][m + j] = -Rational(b[j][r]);
    T[4][m + j] = 1;
  }
  T[3][rhs] = 1;
  T[4][rhs] = 1;
  std::vector<int> basis(kRows);
  for (int r = 0; r < kRows; ++r) {
    T[r][m + n + r] = 1;
    basis[r] = m + n + r;
  }
  // Phase 1 minimises the sum of the artificials: reduced cost of column k is -sum_r T[r][k]
  // (artificials 0), objective row rhs = -sum of the right-hand sides.
  for (int k = 0; k < m + n; ++k) {
    for (int r = 0; r < kRows; ++r) T[kRows][k] -= T[r][k];
  }
  T[kRows][rhs] = -2;
  for (;;) {
    // Bland's rule: the lowest-index column with a negative reduced cost enters.
    int enter = -1;
    for (int k = 0; k < columns; ++k) {
      if (T[kRows][k] < 0) {
        enter = k;
        break;
      }
    }
    if (enter < 0) break;
    // Ratio test; ties broken by the lowest basic variable index (Bland).
    int leave = -1;
    Rational best;
    for (int r = 0; r < kRows; ++r) {
      if (T[r][enter] <= 0) continue;
      const Rational ratio = T[r][rhs] / T[r][enter];
      if (leave < 0 || ratio < best || (ratio == best && basis[r] < basis[leave])) {
        leave = r;
        best = ratio;
      }
    }
    // Phase 1 is bounded below by 0, so a negative reduced cost always has a pivot row.
    if (leave < 0) throw std::logic_error("hulls_intersect_exact_lp: unbounded phase 1");
    const Rational pivot = T[leave][enter];
    for (int k = 0; k <= columns; ++k) T[leave][k] /= pivot;
    for (int r = 0; r <= kRows; ++r) {
      if (r == leave || T[r][enter] == 0) continue;
      const Rational factor = T[r][enter];
      for (int k = 0; k <= columns; ++k) {
        if (T[leave][k] != 0) T[r][k] -= factor * T[leave][k];
      }
    }
    basis[leave] = enter;
  }
  // Optimal phase-1 objective (sum of artificials) is -T[kRows][rhs]; feasible iff it is 0.
  return T[kRows][rhs] == 0;
}

}  // namespace grpvss::test
