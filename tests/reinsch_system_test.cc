#include "solver/spline/reinsch_system.h"

#include <limits>
#include <random>

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace tpopt {
namespace {

constexpr double kNoTolerance = std::numeric_limits<double>::infinity();

struct Data {
  std::vector<double> s, y, y2, w;
};

// Uneven abscissae, two wiggly series and weights with a few points
// down-weighted.
Data MakeData(int n) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> step(0.2, 1.5), noise(-0.05, 0.05);
  Data d;
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    x += step(rng);
    d.s.push_back(x);
    d.y.push_back(std::sin(0.3 * x) + noise(rng));
    d.y2.push_back(0.01 * x * x + noise(rng));
    d.w.push_back(i % 7 == 3 ? 1e-3 : (i % 5 == 1 ? 2.0 : 1.0));
  }
  return d;
}

// Independent truth: the Green & Silverman system assembled as dense
// matrices and solved by Eigen; returns gamma at all knots (zero ends) and
// the fitted values f = y - lambda W^-1 Q gamma.
void DenseFit(const Data& d, const std::vector<double>& y, double lambda,
              std::vector<double>* gamma, std::vector<double>* f) {
  const int n = static_cast<int>(d.s.size()), m = n - 2;
  Eigen::MatrixXd q = Eigen::MatrixXd::Zero(n, m), r = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < m; ++j) {
    const double h0 = d.s[j + 1] - d.s[j], h1 = d.s[j + 2] - d.s[j + 1];
    q(j, j) = 1.0 / h0;
    q(j + 1, j) = -1.0 / h0 - 1.0 / h1;
    q(j + 2, j) = 1.0 / h1;
    r(j, j) = (h0 + h1) / 3.0;
    if (j + 1 < m) r(j, j + 1) = r(j + 1, j) = h1 / 6.0;
  }
  Eigen::VectorXd w_inv(n), yv(n);
  for (int i = 0; i < n; ++i) {
    w_inv[i] = 1.0 / d.w[i];
    yv[i] = y[i];
  }
  const Eigen::MatrixXd a = r + lambda * q.transpose() * w_inv.asDiagonal() * q;
  const Eigen::VectorXd g = a.ldlt().solve(q.transpose() * yv);
  const Eigen::VectorXd fv = yv - lambda * (w_inv.asDiagonal() * (q * g));
  gamma->assign(n, 0.0);
  for (int j = 0; j < m; ++j) (*gamma)[j + 1] = g[j];
  f->assign(fv.data(), fv.data() + n);
}

// Largest |f_i - y_i| over the points of weight >= 1.
double WorstCheckedResidual(const Data& d, const std::vector<double>& y,
                            const std::vector<double>& f) {
  double worst = 0.0;
  for (size_t i = 0; i < y.size(); ++i) {
    if (d.w[i] >= 1.0) worst = std::max(worst, std::abs(f[i] - y[i]));
  }
  return worst;
}

TEST(ReinschSystemTest, SolveMatchesTheDenseSystem) {
  const Data d = MakeData(60);
  ReinschSystem system(d.s, d.w);
  for (double lambda : {0.0, 0.05, 3.0, 400.0}) {
    std::vector<double> gamma, dense_gamma, dense_f;
    ASSERT_EQ(system.Solve(d.y, lambda, kNoTolerance, &gamma), ReinschSystem::Outcome::kWithin);
    DenseFit(d, d.y, lambda, &dense_gamma, &dense_f);
    ASSERT_EQ(gamma.size(), d.s.size());
    EXPECT_EQ(gamma.front(), 0.0);
    EXPECT_EQ(gamma.back(), 0.0);
    for (size_t i = 0; i < gamma.size(); ++i) {
      EXPECT_NEAR(gamma[i], dense_gamma[i], 1e-9) << "lambda " << lambda << " knot " << i;
      EXPECT_NEAR(system.Value(d.y, static_cast<int>(i), lambda, gamma), dense_f[i], 1e-9);
    }
  }
}

TEST(ReinschSystemTest, ToleranceOutcomeFollowsTheWorstWeightedResidual) {
  const Data d = MakeData(80);
  ReinschSystem system(d.s, d.w);
  const double lambda = 2.0;
  std::vector<double> dense_gamma, dense_f, gamma;
  DenseFit(d, d.y, lambda, &dense_gamma, &dense_f);
  const double worst = WorstCheckedResidual(d, d.y, dense_f);
  ASSERT_GT(worst, 1e-3);
  EXPECT_EQ(system.Solve(d.y, lambda, worst * 1.001, &gamma), ReinschSystem::Outcome::kWithin);
  EXPECT_EQ(system.Solve(d.y, lambda, worst * 0.999, &gamma), ReinschSystem::Outcome::kOutside);
}

TEST(ReinschSystemTest, SolveEachEqualsOneSolveASeries) {
  const Data d = MakeData(101);
  ReinschSystem system(d.s, d.w);
  const std::vector<double> y3 = d.y2;  // a third series: a pair and a single
  const std::vector<double> lambdas = {0.7, 25.0, 3.0};
  // A tolerance that the first series meets and the second does not, so
  // one stops early while the other runs to the end.
  std::vector<double> g, f;
  DenseFit(d, d.y, lambdas[0], &g, &f);
  const double tolerance = WorstCheckedResidual(d, d.y, f) * 1.01;
  DenseFit(d, d.y2, lambdas[1], &g, &f);
  ASSERT_GT(WorstCheckedResidual(d, d.y2, f), tolerance);

  std::vector<double> ga, gb, gc;
  const auto outcomes =
      system.SolveEach({&d.y, &d.y2, &y3}, lambdas, tolerance, {&ga, &gb, &gc});
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_EQ(outcomes[0], ReinschSystem::Outcome::kWithin);
  EXPECT_EQ(outcomes[1], ReinschSystem::Outcome::kOutside);
  std::vector<double> alone;
  EXPECT_EQ(system.Solve(d.y, lambdas[0], tolerance, &alone), outcomes[0]);
  EXPECT_EQ(alone, ga);  // bit for bit
  EXPECT_EQ(system.Solve(y3, lambdas[2], tolerance, &alone), outcomes[2]);
  if (outcomes[2] == ReinschSystem::Outcome::kWithin) {
    EXPECT_EQ(alone, gc);
  }
}

}  // namespace
}  // namespace tpopt
