#include "solver/spline/smoothing_spline.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <random>

namespace tpopt {
namespace {

std::vector<double> Range(int n, double step) {
  std::vector<double> s(n);
  for (int i = 0; i < n; ++i) s[i] = i * step + 0.01 * (i % 3);  // uneven
  return s;
}

TEST(SmoothingSplineTest, StraightLinesAreLeftAloneAtAnySmoothing) {
  const std::vector<double> s = Range(20, 0.5);
  std::vector<double> y;
  for (double x : s) y.push_back(3 - 2 * x);
  for (double p : {0.0, 1.0, 1e6}) {
    SmoothingSpline f;
    ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, p, &f).ok());
    for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(f.values()[i], y[i], 1e-9);
    EXPECT_NEAR(f.Evaluate(2.3)[1], -2.0, 1e-9);
    EXPECT_NEAR(f.Evaluate(2.3)[2], 0.0, 1e-9);
  }
}

TEST(SmoothingSplineTest, ZeroSmoothingInterpolatesAndHeavySmoothingIsTheLeastSquaresLine) {
  const std::vector<double> s = Range(30, 1.0);
  std::vector<double> y;
  for (double x : s) y.push_back(std::sin(x));
  SmoothingSpline interp, line;
  ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, 0.0, &interp).ok());
  for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(interp(s[i]), y[i], 1e-12);
  // Continuity of f' and f'' across a knot.
  const auto left = interp.Evaluate(s[10] - 1e-9), right = interp.Evaluate(s[10] + 1e-9);
  EXPECT_NEAR(left[1], right[1], 1e-6);
  EXPECT_NEAR(left[2], right[2], 1e-6);
  ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, 1e12, &line).ok());
  // Least-squares line through the same points, in closed form.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = s.size();
  for (size_t i = 0; i < s.size(); ++i) {
    sx += s[i];
    sy += y[i];
    sxx += s[i] * s[i];
    sxy += s[i] * y[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double intercept = (sy - slope * sx) / n;
  for (size_t i = 0; i < s.size(); ++i) EXPECT_NEAR(line(s[i]), intercept + slope * s[i], 1e-5);
}

TEST(SmoothingSplineTest, DerivativesMatchFiniteDifferences) {
  const std::vector<double> s = Range(25, 0.7);
  std::vector<double> y;
  for (double x : s) y.push_back(std::cos(0.5 * x) + 0.1 * x * x);
  SmoothingSpline f;
  ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, 0.3, &f).ok());
  const double h = 1e-6;
  for (double x : {1.3, 5.55, 12.0}) {
    const auto d = f.Evaluate(x);
    EXPECT_NEAR(d[1], (f(x + h) - f(x - h)) / (2 * h), 1e-6);
    EXPECT_NEAR(d[2], (f.Evaluate(x + h)[1] - f.Evaluate(x - h)[1]) / (2 * h), 1e-5);
  }
}

TEST(SmoothingSplineTest, ToleranceFitSmoothsNoiseButStaysWithinTolerance) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  const std::vector<double> s = Range(400, 0.25);
  std::vector<double> y, clean;
  for (double x : s) {
    clean.push_back(std::sin(0.1 * x));
    y.push_back(clean.back() + noise(rng));
  }
  SmoothingSpline f;
  ASSERT_TRUE(SmoothingSpline::FitWithinTolerance(s, y, {}, 0.04, &f).ok());
  double worst = 0.0, data_bend = 0.0, fit_bend = 0.0;
  for (size_t i = 0; i < s.size(); ++i) {
    worst = std::max(worst, std::abs(f.values()[i] - y[i]));
    if (i == 0 || i + 1 == s.size()) continue;
    auto bend = [&](const std::vector<double>& v) {
      return std::abs(v[i + 1] - 2 * v[i] + v[i - 1]);
    };
    data_bend = std::max(data_bend, bend(y));
    fit_bend = std::max(fit_bend, bend(f.values()));
  }
  EXPECT_LE(worst, 0.04);
  EXPECT_GT(f.smoothing(), 1.0);
  // The noise's kinks are gone: the fit's peak second difference is a small
  // fraction of the noisy data's.
  EXPECT_LT(fit_bend, 0.05 * data_bend);
}

TEST(SmoothingSplineTest, DownWeightedPointsAreIgnored) {
  const std::vector<double> s = Range(50, 1.0);
  std::vector<double> y, w(50, 1.0);
  for (double x : s) y.push_back(0.2 * x);
  y[25] += 5.0;  // a spike
  w[25] = 1e-6;
  SmoothingSpline f;
  ASSERT_TRUE(SmoothingSpline::FitWithinTolerance(s, y, w, 1e-3, &f).ok());
  EXPECT_NEAR(f(s[25]), 0.2 * s[25], 1e-2);
}

TEST(SmoothingSplineTest, FitEachIsFitWithinToleranceOfEverySeries) {
  // Three series (one pair solved together, one alone) on shared
  // abscissae and weights, as the A and C of a path are fitted.
  const std::vector<double> s = Range(300, 0.3);
  std::vector<double> a, c, b, w(s.size(), 1.0);
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.004);
  for (size_t i = 0; i < s.size(); ++i) {
    a.push_back(std::sin(0.05 * s[i]) + noise(rng));
    c.push_back(0.3 * s[i] + (i > 150 && i < 160 ? 0.5 : 0.0) + noise(rng));
    b.push_back(std::cos(0.2 * s[i]));
    if (i > 148 && i < 162) w[i] = 1e-4;
  }
  SmoothingSpline fa, fc, fb;
  ASSERT_TRUE(SmoothingSpline::FitEachWithinTolerance(s, {&a, &c, &b}, w, 0.01, {&fa, &fc, &fb})
                  .ok());
  const std::vector<const std::vector<double>*> ys = {&a, &c, &b};
  const std::vector<const SmoothingSpline*> fits = {&fa, &fc, &fb};
  for (size_t k = 0; k < ys.size(); ++k) {
    SmoothingSpline alone;
    ASSERT_TRUE(SmoothingSpline::FitWithinTolerance(s, *ys[k], w, 0.01, &alone).ok());
    EXPECT_EQ(fits[k]->smoothing(), alone.smoothing()) << "series " << k;
    EXPECT_EQ(fits[k]->values(), alone.values()) << "series " << k;
    EXPECT_EQ(fits[k]->Evaluate(40.05), alone.Evaluate(40.05)) << "series " << k;
  }
}

TEST(SmoothingSplineTest, ScalesLinearlyToAMillionPoints) {
  const int n = 1000000;
  std::vector<double> s(n), y(n);
  for (int i = 0; i < n; ++i) {
    s[i] = i * 0.01;
    y[i] = std::sin(s[i]);
  }
  SmoothingSpline f;
  ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, 1.0, &f).ok());
  EXPECT_NEAR(f(5000.005), std::sin(5000.005), 1e-3);
}

// Not-a-knot ends hold any cubic exactly (a natural spline's would bend it
// straight at the ends), with its derivatives; three points give the
// parabola through them, two the line.
TEST(SmoothingSplineTest, NotAKnotInterpolationIsExactOnCubics) {
  const auto cubic = [](double x) { return 0.7 - 1.3 * x + 0.4 * x * x - 0.05 * x * x * x; };
  for (int n : {4, 5, 9, 40}) {
    // Steps of 0.2-0.5, unequal at both ends (h0 != h1, h_n-2 != h_n-3).
    std::vector<double> s = {0.0};
    for (int i = 0; i + 1 < n; ++i) s.push_back(s.back() + 0.2 + 0.3 * ((i * 7 + n) % 5) / 4.0);
    std::vector<double> y;
    for (double x : s) y.push_back(cubic(x));
    SmoothingSpline f;
    ASSERT_TRUE(SmoothingSpline::InterpolateNotAKnot(s, y, &f).ok()) << n;
    for (double x = s.front(); x <= s.back(); x += 0.013) {
      const std::array<double, 4> v = f.Evaluate(x);
      EXPECT_NEAR(v[0], cubic(x), 1e-12) << n << " " << x;
      EXPECT_NEAR(v[1], -1.3 + 0.8 * x - 0.15 * x * x, 1e-11) << n << " " << x;
      EXPECT_NEAR(v[2], 0.8 - 0.3 * x, 1e-10) << n << " " << x;
      EXPECT_NEAR(v[3], -0.3, 1e-9) << n << " " << x;
    }
  }
  SmoothingSpline parabola, line;
  // (x - 1)^2 through three points.
  ASSERT_TRUE(
      SmoothingSpline::InterpolateNotAKnot({0.0, 0.5, 2.0}, {1.0, 0.25, 1.0}, &parabola).ok());
  EXPECT_NEAR(parabola(1.0), 0.0, 1e-12);
  EXPECT_NEAR(parabola(1.5), 0.25, 1e-12);
  EXPECT_NEAR(parabola.Evaluate(1.7)[2], 2.0, 1e-12);
  ASSERT_TRUE(SmoothingSpline::InterpolateNotAKnot({1.0, 3.0}, {2.0, 6.0}, &line).ok());
  EXPECT_NEAR(line(2.5), 5.0, 1e-12);
  EXPECT_FALSE(SmoothingSpline::InterpolateNotAKnot({0, 1, 1, 2}, {0, 0, 0, 0}, &line).ok());
  EXPECT_FALSE(SmoothingSpline::InterpolateNotAKnot({0}, {0}, &line).ok());
}

// On data with curvature at its ends the natural spline is not exact near
// them, which is what the not-a-knot interpolant is for.
TEST(SmoothingSplineTest, NaturalEndsBendAParabolaThatNotAKnotEndsKeep) {
  const std::vector<double> s = Range(12, 1.0);
  std::vector<double> y;
  for (double x : s) y.push_back(x * x);
  SmoothingSpline natural, not_a_knot;
  ASSERT_TRUE(SmoothingSpline::Fit(s, y, {}, 0.0, &natural).ok());
  ASSERT_TRUE(SmoothingSpline::InterpolateNotAKnot(s, y, &not_a_knot).ok());
  const double x = 0.5 * (s[0] + s[1]);
  EXPECT_GT(std::abs(natural(x) - x * x), 1e-3);
  EXPECT_NEAR(not_a_knot(x), x * x, 1e-12);
}

TEST(SmoothingSplineTest, RejectsBadInputNamingTheIndex) {
  SmoothingSpline f;
  Status st = SmoothingSpline::Fit({0, 1, 1, 2}, {0, 0, 0, 0}, {}, 1.0, &f);
  ASSERT_FALSE(st.ok());
  EXPECT_NE(st.message().find("point 2"), std::string::npos) << st.message();
  EXPECT_FALSE(SmoothingSpline::Fit({0}, {0}, {}, 1.0, &f).ok());
  EXPECT_FALSE(SmoothingSpline::Fit({0, 1}, {0, 1}, {1, 0}, 1.0, &f).ok());
}

}  // namespace
}  // namespace tpopt
