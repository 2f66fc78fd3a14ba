#include "solver/spline/reinsch_system.h"

#include <cmath>

namespace tpopt {

ReinschSystem::ReinschSystem(const std::vector<double>& s, const std::vector<double>& weights)
    : s_(s), weights_(weights), m_(static_cast<int>(s.size()) - 2),
      inv_h_(s.size() - 1), w_inv_(s.size()) {
  for (size_t i = 0; i + 1 < s.size(); ++i) inv_h_[i] = 1.0 / (s[i + 1] - s[i]);
  for (size_t i = 0; i < s.size(); ++i) w_inv_[i] = weights.empty() ? 1.0 : 1.0 / weights[i];
}

ReinschSystem::Outcome ReinschSystem::Solve(const std::vector<double>& y, double lambda,
                                            double tolerance, std::vector<double>* gamma) {
  return SolveEach({&y}, {lambda}, tolerance, {gamma})[0];
}

std::vector<ReinschSystem::Outcome> ReinschSystem::SolveEach(
    const std::vector<const std::vector<double>*>& ys, const std::vector<double>& lambdas,
    double tolerance, const std::vector<std::vector<double>*>& gammas) {
  std::vector<Outcome> outcomes;
  size_t k = 0;
  for (; k + 1 < ys.size(); k += 2) {
    const auto pair = SolveGroup<2>(ys, lambdas, tolerance, gammas, k);
    outcomes.insert(outcomes.end(), pair.begin(), pair.end());
  }
  if (k < ys.size()) outcomes.push_back(SolveGroup<1>(ys, lambdas, tolerance, gammas, k)[0]);
  return outcomes;
}

template <int K>
std::array<ReinschSystem::Outcome, K> ReinschSystem::SolveGroup(
    const std::vector<const std::vector<double>*>& ys, const std::vector<double>& lambdas,
    double tolerance, const std::vector<std::vector<double>*>& gammas, size_t first) {
  std::array<const std::vector<double>*, K> y;
  std::array<double, K> lambda;
  std::array<std::vector<double>*, K> gamma;
  for (int k = 0; k < K; ++k) {
    y[k] = ys[first + k];
    lambda[k] = lambdas[first + k];
    gamma[k] = gammas[first + k];
  }
  if (!Factor<K>(y, lambda, gamma)) {
    std::array<Outcome, K> singular;
    singular.fill(Outcome::kSingular);
    return singular;
  }
  return BackSubstitute<K>(y, lambda, tolerance, gamma);
}

// Column j of Q (knot j + 1) has q0 = 1/h_j, q1 = -1/h_j - 1/h_j+1 and
// q2 = 1/h_j+1 at rows j, j + 1, j + 2; R has (h_j + h_j+1)/3 on the
// diagonal and h_j+1/6 beside it. Row j of the pentadiagonal system is
// d0 (diagonal), d1 and d2 (the two right of it); the parts that do not
// depend on lambda are shared by the K series. The previous two rows of
// each series ride in registers, zero before the first, so the recurrences
// need no branches. False when a series' system is not positive definite.
template <int K>
bool ReinschSystem::Factor(const std::array<const std::vector<double>*, K>& y,
                           const std::array<double, K>& lambda,
                           const std::array<std::vector<double>*, K>& gamma) {
  const std::vector<double>& ih = inv_h_;
  const std::vector<double>& w = w_inv_;
  struct Row {
    double dd, l1, l2, z;
  };
  std::array<Row, K> p1{}, p2{};  // rows j - 1 and j - 2
  pivots_.resize(static_cast<size_t>(m_) * K);
  for (int k = 0; k < K; ++k) {
    gamma[k]->resize(m_ + 2);
    gamma[k]->front() = gamma[k]->back() = 0.0;
  }
  for (int j = 0; j < m_; ++j) {
    const double h0 = s_[j + 1] - s_[j], h1 = s_[j + 2] - s_[j + 1];
    const double q0 = ih[j], q1 = -ih[j] - ih[j + 1], q2 = ih[j + 1];
    const double r0 = (h0 + h1) / 3.0;
    const double c0 = q0 * q0 * w[j] + q1 * q1 * w[j + 1] + q2 * q2 * w[j + 2];
    const bool has_d1 = j + 1 < m_, has_d2 = j + 2 < m_;
    const double r1 = h1 / 6.0;
    const double c1 = has_d1 ? q1 * q2 * w[j + 1] + q2 * (-ih[j + 1] - ih[j + 2]) * w[j + 2] : 0.0;
    for (int k = 0; k < K; ++k) {
      const std::vector<double>& yk = *y[k];
      const double rhs = q0 * yk[j] + q1 * yk[j + 1] + q2 * yk[j + 2];
      const double diag = r0 + lambda[k] * c0 - p1[k].l1 * p1[k].l1 * p1[k].dd -
                          p2[k].l2 * p2[k].l2 * p2[k].dd;
      if (!(diag > 0)) return false;
      Row p{diag, 0.0, 0.0, rhs - p1[k].l1 * p1[k].z - p2[k].l2 * p2[k].z};
      if (has_d1) p.l1 = (r1 + lambda[k] * c1 - p1[k].l2 * p1[k].l1 * p1[k].dd) / diag;
      if (has_d2) p.l2 = lambda[k] * q2 * ih[j + 2] * w[j + 2] / diag;
      pivots_[static_cast<size_t>(j) * K + k] = {p.l1, p.l2};
      (*gamma[k])[j + 1] = p.z / p.dd;
      p2[k] = p1[k];
      p1[k] = p;
    }
  }
  return true;
}

// L^T gamma = z / D, in place, from the last interior knot back; once knot
// j + 1 (column j) is known, row j + 2 has all three of its columns and is
// tested. A series found outside keeps being computed (free, beside the
// other's recurrence) but no longer tested; the sweep stops when all are.
template <int K>
std::array<ReinschSystem::Outcome, K> ReinschSystem::BackSubstitute(
    const std::array<const std::vector<double>*, K>& y, const std::array<double, K>& lambda,
    double tolerance, const std::array<std::vector<double>*, K>& gamma) {
  std::array<Outcome, K> outcome;
  outcome.fill(Outcome::kWithin);
  int within = K;
  auto test = [&](int k, int i) {
    if (outcome[k] != Outcome::kWithin || !Checked(i)) return;
    if (std::abs(Value(*y[k], i, lambda[k], *gamma[k]) - (*y[k])[i]) > tolerance) {
      outcome[k] = Outcome::kOutside;
      --within;
    }
  };
  std::array<double, K> g1{}, g2{};  // gamma at knots j + 2 and j + 3
  for (int j = m_ - 1; j >= 0 && within > 0; --j) {
    for (int k = 0; k < K; ++k) {
      const Pivot& p = pivots_[static_cast<size_t>(j) * K + k];
      double& g = (*gamma[k])[j + 1];  // z / D until now
      const double gj = g - p.l1 * g1[k] - p.l2 * g2[k];
      g = gj;
      g2[k] = g1[k];
      g1[k] = gj;
    }
    for (int k = 0; k < K; ++k) test(k, j + 2);
  }
  for (int k = 0; k < K && within > 0; ++k) {
    test(k, 1);
    test(k, 0);
  }
  return outcome;
}

}  // namespace tpopt
