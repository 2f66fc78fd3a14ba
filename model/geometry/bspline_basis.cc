#include "model/geometry/bspline_basis.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

namespace tpopt {

Status NormalizeClampedKnots(int degree, size_t num_control_points, const std::string& what,
                             std::vector<double>* knots_in_out) {
  std::vector<double>& knots = *knots_in_out;
  std::ostringstream err;
  if (degree < 1 || degree > kMaxBSplineDegree) {
    err << what << ": degree " << degree << " is outside [1, " << kMaxBSplineDegree << "]";
    return Status::Error(err.str());
  }
  const size_t n = num_control_points;
  if (n < static_cast<size_t>(degree) + 1) {
    err << what << ": " << n << " control points are too few for degree " << degree
        << " (need at least " << degree + 1 << ")";
    return Status::Error(err.str());
  }
  if (knots.size() != n + degree + 1) {
    err << what << ": " << knots.size() << " knots, but " << n << " control points of degree "
        << degree << " need " << n + degree + 1;
    return Status::Error(err.str());
  }
  for (size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) {
      err << what << ": knot " << i << " is not finite (" << knots[i] << ")";
      return Status::Error(err.str());
    }
    if (i > 0 && knots[i] < knots[i - 1]) {
      err << what << ": knots decrease at index " << i << " (" << knots[i - 1] << " then "
          << knots[i] << ")";
      return Status::Error(err.str());
    }
  }
  for (int i = 1; i <= degree; ++i) {
    if (knots[i] != knots[0] || knots[knots.size() - 1 - i] != knots.back()) {
      err << what << ": knot vector is not clamped (the first and last " << degree + 1
          << " knots must be equal)";
      return Status::Error(err.str());
    }
  }
  const double lo = knots.front(), hi = knots.back();
  if (!(hi > lo)) {
    err << what << ": knot range is empty [" << lo << ", " << hi << "]";
    return Status::Error(err.str());
  }
  for (double& k : knots) k = (k - lo) / (hi - lo);
  knots.front() = 0.0;
  knots.back() = 1.0;
  return Status::Ok();
}

int FindKnotSpan(const std::vector<double>& knots, int degree, int num_control_points, double u) {
  const int n = num_control_points - 1;
  if (u >= knots[n + 1]) return n;
  if (u <= knots[degree]) {
    // Skip any zero-length spans at the start.
    int span = degree;
    while (span < n && knots[span + 1] <= u) ++span;
    return span;
  }
  // Largest span with knots[span] <= u < knots[span + 1].
  auto it = std::upper_bound(knots.begin() + degree, knots.begin() + n + 1, u);
  return static_cast<int>(it - knots.begin()) - 1;
}

void ComputeBasisDerivatives(const std::vector<double>& knots, int p, int span, double u,
                             int max_order, BasisDerivatives ders) {
  CHECK(max_order >= 0 && max_order <= kMaxBasisOrder);
  CHECK(p >= 1 && p <= kMaxBSplineDegree);
  const int nd = std::min(max_order, p);
  // Piegl & Tiller A2.3, with stack buffers sized by kMaxBSplineDegree.
  constexpr int K = kMaxBSplineDegree + 1;
  double ndu[K][K];
  double left[K], right[K];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - knots[span + 1 - j];
    right[j] = knots[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int k = 0; k <= max_order; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] = 0.0;
  }
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  double a[2][K];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = (rk >= -1) ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) ders[k][j] *= factor;
    factor *= (p - k);
  }
}

}  // namespace tpopt
