// Properties of the divided-difference derivative weights: exact on every
// polynomial of their degree at uneven (and even) spacing, blind to lower
// degrees, and the familiar differences on a uniform grid.
#include "solver/smooth/cost/divided_difference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace tpopt {
namespace {

// k random strictly increasing abscissae with gaps in [0.05, 2], from a
// start in [-5, 5].
template <int kOrder>
std::array<double, kOrder + 1> UnevenAbscissae(std::mt19937* rng) {
  std::uniform_real_distribution<double> start(-5, 5), gap(0.05, 2.0);
  std::array<double, kOrder + 1> s;
  s[0] = start(*rng);
  for (int j = 1; j <= kOrder; ++j) s[j] = s[j - 1] + gap(*rng);
  return s;
}

double Factorial(int k) { return k <= 1 ? 1.0 : k * Factorial(k - 1); }

// sum_j c_j p(s_j) for p(s) = sum_m coefficients[m] s^m.
template <int kOrder, int kDegree>
double Apply(const std::array<double, kOrder + 1>& c, const std::array<double, kDegree + 1>& p,
             const std::array<double, kOrder + 1>& s) {
  double sum = 0.0;
  for (int j = 0; j <= kOrder; ++j) {
    double value = 0.0;
    for (int m = kDegree; m >= 0; --m) value = value * s[j] + p[m];
    sum += c[j] * value;
  }
  return sum;
}

// The k-th derivative of a degree-k polynomial is k! times its leading
// coefficient everywhere; polynomials of lower degree give 0.
template <int kOrder>
void ExpectExactOnPolynomials(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coefficient(-3, 3);
  for (int draw = 0; draw < 50; ++draw) {
    const std::array<double, kOrder + 1> s = UnevenAbscissae<kOrder>(&rng);
    const std::array<double, kOrder + 1> c = DerivativeWeights<kOrder>(s);
    std::array<double, kOrder + 1> p;
    for (double& v : p) v = coefficient(rng);
    // Round-off: the weights grow like 1/gap^k and the values like |s|^k.
    double scale = 0.0;
    for (int j = 0; j <= kOrder; ++j) scale += std::abs(c[j]) * std::pow(1 + std::abs(s[j]), kOrder);
    EXPECT_NEAR((Apply<kOrder, kOrder>(c, p, s)), Factorial(kOrder) * p[kOrder], 1e-12 * scale)
        << "order " << kOrder << ", draw " << draw;
    std::array<double, kOrder> lower;
    for (int m = 0; m < kOrder; ++m) lower[m] = p[m];
    EXPECT_NEAR((Apply<kOrder, kOrder - 1>(c, lower, s)), 0.0, 1e-12 * scale)
        << "order " << kOrder << ", draw " << draw;
  }
}

TEST(DividedDifferencePropertyTest, ExactOnPolynomialsOfTheirDegreeAtUnevenSpacing) {
  ExpectExactOnPolynomials<1>(1);
  ExpectExactOnPolynomials<2>(2);
  ExpectExactOnPolynomials<3>(3);
  ExpectExactOnPolynomials<4>(4);
}

TEST(DividedDifferencePropertyTest, UniformSpacingGivesTheFamiliarDifferences) {
  const double h = 0.25;
  const std::array<double, 2> c1 = DerivativeWeights<1>({1.0, 1.0 + h});
  EXPECT_NEAR(c1[0], -1 / h, 1e-12);
  EXPECT_NEAR(c1[1], 1 / h, 1e-12);
  const std::array<double, 3> c2 = DerivativeWeights<2>({1.0, 1.0 + h, 1.0 + 2 * h});
  const double h2 = h * h;
  EXPECT_NEAR(c2[0], 1 / h2, 1e-12);
  EXPECT_NEAR(c2[1], -2 / h2, 1e-12);
  EXPECT_NEAR(c2[2], 1 / h2, 1e-12);
  const std::array<double, 4> c3 = DerivativeWeights<3>({1.0, 1.0 + h, 1.0 + 2 * h, 1.0 + 3 * h});
  const double h3 = h2 * h;
  EXPECT_NEAR(c3[0], -1 / h3, 1e-10);
  EXPECT_NEAR(c3[1], 3 / h3, 1e-10);
  EXPECT_NEAR(c3[2], -3 / h3, 1e-10);
  EXPECT_NEAR(c3[3], 1 / h3, 1e-10);
}

// The weights of a derivative do not depend on where the grid sits: shifting
// every abscissa by the same amount leaves them unchanged.
TEST(DividedDifferencePropertyTest, WeightsAreShiftInvariant) {
  std::mt19937 rng(7);
  for (int draw = 0; draw < 50; ++draw) {
    const std::array<double, 4> s = UnevenAbscissae<3>(&rng);
    std::array<double, 4> shifted = s;
    for (double& v : shifted) v += 37.5;
    const std::array<double, 4> c = DerivativeWeights<3>(s), d = DerivativeWeights<3>(shifted);
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(c[j], d[j], 1e-9 * std::max(1.0, std::abs(c[j]))) << "draw " << draw;
    }
  }
}

}  // namespace
}  // namespace tpopt
