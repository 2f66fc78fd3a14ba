// Weights of the k-th derivative estimate from k + 1 samples at arbitrary,
// increasing abscissae: f^(k) ~= k! f[s_0, ..., s_k] = sum_j c_j f(s_j) with
// c_j = k! / prod_{m != j} (s_j - s_m). Exact for polynomials of degree k;
// for uniform spacing h it is the familiar k-th difference / h^k.
#ifndef TPOPT_SOLVER_DIVIDED_DIFFERENCE_H_
#define TPOPT_SOLVER_DIVIDED_DIFFERENCE_H_

#include <array>

#include <glog/logging.h>

namespace tpopt {

template <int kOrder>
std::array<double, kOrder + 1> DerivativeWeights(const std::array<double, kOrder + 1>& s) {
  double factorial = 1.0;
  for (int k = 2; k <= kOrder; ++k) factorial *= k;
  std::array<double, kOrder + 1> c;
  for (int j = 0; j <= kOrder; ++j) {
    double denominator = 1.0;
    for (int m = 0; m <= kOrder; ++m) {
      if (m != j) denominator *= s[j] - s[m];
    }
    CHECK_NE(denominator, 0.0) << "repeated abscissa in a divided difference";
    c[j] = factorial / denominator;
  }
  return c;
}

}  // namespace tpopt

#endif  // TPOPT_SOLVER_DIVIDED_DIFFERENCE_H_
