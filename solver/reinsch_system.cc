#include "solver/reinsch_system.h"

#include <cmath>

namespace tpopt {

ReinschSystem::ReinschSystem(const std::vector<double>& s, const std::vector<double>& weights)
    : s_(s), weights_(weights), m_(static_cast<int>(s.size()) - 2),
      inv_h_(s.size() - 1), w_inv_(s.size()), pivots_(m_) {
  for (size_t i = 0; i + 1 < s.size(); ++i) inv_h_[i] = 1.0 / (s[i + 1] - s[i]);
  for (size_t i = 0; i < s.size(); ++i) w_inv_[i] = weights.empty() ? 1.0 : 1.0 / weights[i];
}

// Column j of Q (knot j + 1) has q0 = 1/h_j, q1 = -1/h_j - 1/h_j+1 and
// q2 = 1/h_j+1 at rows j, j + 1, j + 2; R has (h_j + h_j+1)/3 on the
// diagonal and h_j+1/6 beside it. Row j of the pentadiagonal system is
// d0 (diagonal), d1 and d2 (the two right of it). The previous two rows
// ride in registers, zero before the first, so the recurrences need no
// branches.
void ReinschSystem::Factor(const std::vector<double>& y, double lambda) {
  const std::vector<double>& ih = inv_h_;
  const std::vector<double>& w = w_inv_;
  struct Row {
    double dd, l1, l2, z;
  };
  Row p1{0, 0, 0, 0}, p2{0, 0, 0, 0};  // rows j - 1 and j - 2
  singular_ = false;
  for (int j = 0; j < m_; ++j) {
    const double h0 = s_[j + 1] - s_[j], h1 = s_[j + 2] - s_[j + 1];
    const double q0 = ih[j], q1 = -ih[j] - ih[j + 1], q2 = ih[j + 1];
    const double d0 = (h0 + h1) / 3.0 + lambda * (q0 * q0 * w[j] + q1 * q1 * w[j + 1] +
                                                  q2 * q2 * w[j + 2]);
    const double rhs = q0 * y[j] + q1 * y[j + 1] + q2 * y[j + 2];
    const double diag = d0 - p1.l1 * p1.l1 * p1.dd - p2.l2 * p2.l2 * p2.dd;
    if (!(diag > 0)) {
      singular_ = true;
      return;
    }
    Row p{diag, 0.0, 0.0, rhs - p1.l1 * p1.z - p2.l2 * p2.z};
    if (j + 1 < m_) {
      const double q1_next = -ih[j + 1] - ih[j + 2];
      const double d1 = h1 / 6.0 + lambda * (q1 * q2 * w[j + 1] + q2 * q1_next * w[j + 2]);
      p.l1 = (d1 - p1.l2 * p1.l1 * p1.dd) / diag;
    }
    if (j + 2 < m_) p.l2 = lambda * q2 * ih[j + 2] * w[j + 2] / diag;
    pivots_[j] = {p.l1, p.l2, p.z / p.dd};
    p2 = p1;
    p1 = p;
  }
}

ReinschSystem::Outcome ReinschSystem::Solve(const std::vector<double>& y, double lambda,
                                            double tolerance, std::vector<double>* gamma) {
  Factor(y, lambda);
  if (singular_) return Outcome::kSingular;
  gamma->resize(m_ + 2);
  std::vector<double>& g = *gamma;
  g.front() = g.back() = 0.0;
  auto outside = [&](int i) {
    return Checked(i) && std::abs(Value(y, i, lambda, g) - y[i]) > tolerance;
  };
  // L^T gamma = z / D from the last interior knot back; once knot j + 1
  // (column j) is known, row j + 2 has all three of its columns and can be
  // tested.
  double g1 = 0.0, g2 = 0.0;  // gamma[j + 1], gamma[j + 2]
  for (int j = m_ - 1; j >= 0; --j) {
    const Pivot& p = pivots_[j];
    const double gj = p.z_over_d - p.l1 * g1 - p.l2 * g2;
    g[j + 1] = gj;
    g2 = g1;
    g1 = gj;
    if (outside(j + 2)) return Outcome::kOutside;
  }
  return outside(1) || outside(0) ? Outcome::kOutside : Outcome::kWithin;
}

double ReinschSystem::Value(const std::vector<double>& y, int i, double lambda,
                            const std::vector<double>& gamma) const {
  // Rows take columns i - 2 (its q2), i - 1 (q1) and i (q0), in this order;
  // column j is knot j + 1.
  const double lw = lambda * w_inv_[i];
  double f = y[i];
  if (i >= 2) f -= lw * inv_h_[i - 1] * gamma[i - 1];
  if (i >= 1 && i - 1 < m_) f -= lw * (-inv_h_[i - 1] - inv_h_[i]) * gamma[i];
  if (i < m_) f -= lw * inv_h_[i] * gamma[i + 1];
  return f;
}

}  // namespace tpopt
