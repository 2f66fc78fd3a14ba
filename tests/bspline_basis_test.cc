// Properties of the B-spline basis (model/geometry/bspline_basis.h): at random
// parameters and at every knot, for degrees 1-5, the basis functions are a
// partition of unity, never negative, and agree with the Cox-de Boor
// recursion written out from its definition; their derivatives sum to zero.
// Clamped knot vectors (the files' kind, normalised to [0, 1]) and
// unclamped uniform ones (evaluated inside [t_p, t_n], where the basis is
// complete) both.
#include "model/geometry/bspline_basis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace tpopt {
namespace {

// N_{i,p}(u) from the recursive definition, half-open spans [t_i, t_i+1),
// the last non-empty span closed at its right end `u_max`.
double CoxDeBoor(const std::vector<double>& t, int i, int p, double u, double u_max) {
  if (p == 0) {
    if (t[i] <= u && u < t[i + 1]) return 1.0;
    // u at the end of the range belongs to the last non-empty span.
    return u == u_max && t[i] < t[i + 1] && t[i + 1] == u_max ? 1.0 : 0.0;
  }
  double value = 0.0;
  if (t[i + p] > t[i]) value += (u - t[i]) / (t[i + p] - t[i]) * CoxDeBoor(t, i, p - 1, u, u_max);
  if (t[i + p + 1] > t[i + 1]) {
    value += (t[i + p + 1] - u) / (t[i + p + 1] - t[i + 1]) * CoxDeBoor(t, i + 1, p - 1, u, u_max);
  }
  return value;
}

// A clamped knot vector for n control points of degree p: interior knots
// at random in (0, 1), one of them doubled when there is room.
std::vector<double> RandomClampedKnots(int p, int n, std::mt19937* rng) {
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  std::vector<double> interior(n - p - 1);
  for (double& k : interior) k = unit(*rng);
  std::sort(interior.begin(), interior.end());
  if (interior.size() >= 2 && p >= 2) interior[1] = interior[0];  // a double knot
  std::vector<double> knots(p + 1, 0.0);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), p + 1, 1.0);
  return knots;
}

// Checks the properties at u in span `span` of `knots`.
void ExpectBasisProperties(const std::vector<double>& knots, int p, int span, double u,
                           double u_max, const std::string& where) {
  BasisDerivatives ders;
  ComputeBasisDerivatives(knots, p, span, u, kMaxBasisOrder, ders);
  double sum = 0.0;
  for (int j = 0; j <= p; ++j) {
    EXPECT_GE(ders[0][j], 0.0) << where << ", j " << j;
    sum += ders[0][j];
    EXPECT_NEAR(ders[0][j], CoxDeBoor(knots, span - p + j, p, u, u_max), 1e-12)
        << where << ", j " << j;
  }
  EXPECT_NEAR(sum, 1.0, 1e-13) << where;
  for (int k = 1; k <= kMaxBasisOrder; ++k) {
    double dsum = 0.0, scale = 1.0;
    for (int j = 0; j <= p; ++j) {
      dsum += ders[k][j];
      scale += std::abs(ders[k][j]);
    }
    EXPECT_NEAR(dsum, 0.0, 1e-11 * scale) << where << ", derivative " << k;
  }
}

TEST(BSplineBasisPropertyTest, ClampedPartitionOfUnityNonNegativeAndCoxDeBoor) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int p = 1; p <= 5; ++p) {
    for (int trial = 0; trial < 4; ++trial) {
      const int n = p + 1 + 2 * trial;  // Bezier first, then interior knots
      std::vector<double> knots = RandomClampedKnots(p, n, &rng);
      ASSERT_TRUE(NormalizeClampedKnots(p, n, "test", &knots).ok());
      std::vector<double> us(knots.begin(), knots.end());  // every knot
      for (int k = 0; k < 50; ++k) us.push_back(unit(rng));
      for (double u : us) {
        const int span = FindKnotSpan(knots, p, n, u);
        const std::string where =
            "degree " + std::to_string(p) + ", n " + std::to_string(n) + ", u " + std::to_string(u);
        ASSERT_GE(span, p) << where;
        ASSERT_LE(span, n - 1) << where;
        EXPECT_LT(knots[span], knots[span + 1]) << where << ": an empty span";
        EXPECT_TRUE(knots[span] <= u && (u < knots[span + 1] || (u == 1.0 && span == n - 1)))
            << where;
        ExpectBasisProperties(knots, p, span, u, 1.0, where);
      }
    }
  }
}

TEST(BSplineBasisPropertyTest, UnclampedUniformPartitionOfUnityInsideTheValidRange) {
  std::mt19937 rng(12);
  for (int p = 1; p <= 5; ++p) {
    const int n = p + 6;
    std::vector<double> knots(n + p + 1);
    for (size_t i = 0; i < knots.size(); ++i) knots[i] = 0.5 * i - 1.0;  // uniform, unclamped
    const double lo = knots[p], hi = knots[n];
    std::uniform_real_distribution<double> inside(lo, hi);
    std::vector<double> us(knots.begin() + p, knots.begin() + n);  // knots in [lo, hi)
    for (int k = 0; k < 50; ++k) us.push_back(inside(rng));
    for (double u : us) {
      // The span by search over the valid range.
      int span = p;
      while (span < n - 1 && knots[span + 1] <= u) ++span;
      const std::string where = "uniform, degree " + std::to_string(p) + ", u " + std::to_string(u);
      ExpectBasisProperties(knots, p, span, u, hi, where);
    }
  }
}

TEST(BSplineBasisPropertyTest, RejectsUnclampedKnotsNamingTheProblem) {
  std::vector<double> knots = {0, 1, 2, 3, 4, 5, 6, 7};  // 4 points of degree 3, unclamped
  const Status s = NormalizeClampedKnots(3, 4, "rail 0", &knots);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("rail 0: knot vector is not clamped"), std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace tpopt
