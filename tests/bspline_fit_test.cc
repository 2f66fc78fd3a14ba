// The seed-004 local fit against closed forms: circles (arc length known),
// a helix, a straight line, and the independent B-spline evaluator of
// model/geometry/bspline_curve.
#include "solver/fit/bspline_fit.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "model/geometry/bspline_curve.h"

namespace tpopt {
namespace {

constexpr Parametrization kAll[] = {Parametrization::kUniform, Parametrization::kChordLength,
                                    Parametrization::kCentripetal,
                                    Parametrization::kApproximateArc};

// A helix of radius r and rise c per radian, by arc length s.
struct Helix {
  double r = 10.0, c = 2.0;
  double Speed() const { return std::hypot(r, c); }
  Eigen::Vector3d Point(double s) const {
    const double t = s / Speed();
    return {r * std::cos(t), r * std::sin(t), c * t};
  }
  Eigen::Vector3d Tangent(double s) const {
    const double t = s / Speed();
    return Eigen::Vector3d(-r * std::sin(t), r * std::cos(t), c) / Speed();
  }
};

void Window(const Helix& h, const std::array<double, 4>& s, std::array<Eigen::Vector3d, 4>* p,
            std::array<Eigen::Vector3d, 4>* t) {
  for (int k = 0; k < 4; ++k) {
    (*p)[k] = h.Point(s[k]);
    (*t)[k] = h.Tangent(s[k]);
  }
}

BSplineCurve AsCurve(const WindowFit& fit) {
  BSplineCurve curve;
  const std::vector<double> knots = {0, 0, 0, 0, fit.knot_a, fit.knot_b, 1, 1, 1, 1};
  const std::vector<Eigen::Vector3d> points(fit.control_points.begin(), fit.control_points.end());
  EXPECT_TRUE(BSplineCurve::Create(3, knots, points, "window", &curve).ok());
  return curve;
}

TEST(ApproximateArcTest, ReproducesTheArcOfACircleFromItsChordAndSagitta) {
  const double radius = 7.0;
  // Half angles up to more than a quarter turn: arcs beyond a half circle.
  for (double half_angle : {1e-4, 0.01, 0.3, 1.2, M_PI / 2, 2.5}) {
    const double chord = 2 * radius * std::sin(half_angle);
    const double sagitta = radius * (1 - std::cos(half_angle));
    EXPECT_NEAR(ApproximateArcLength(chord, sagitta), 2 * radius * half_angle, 1e-9)
        << half_angle;
    EXPECT_NEAR(ApproximateArcRadius(chord, sagitta), radius, 1e-6) << half_angle;
  }
  EXPECT_DOUBLE_EQ(ApproximateArcLength(0.4, 0.0), 0.4);
  EXPECT_TRUE(std::isinf(ApproximateArcRadius(0.4, 0.0)));
}

TEST(FitWindowTest, PassesThroughTheFourPointsWithTheSeedsEndTangents) {
  const Helix helix;
  std::array<Eigen::Vector3d, 4> p, t;
  Window(helix, {3.0, 3.25, 3.9, 4.1}, &p, &t);  // uneven spacing
  for (Parametrization kind : kAll) {
    LocalFitOptions options;
    options.parametrization = kind;
    WindowFit fit;
    ASSERT_TRUE(FitWindow(p, t, options, 0, &fit).ok());
    ASSERT_LT(0.0, fit.knot_a);
    ASSERT_LT(fit.knot_a, fit.knot_b);
    ASSERT_LT(fit.knot_b, 1.0);
    const BSplineCurve curve = AsCurve(fit);
    EXPECT_LT((curve.Point(0) - p[0]).norm(), 1e-12);
    EXPECT_LT((curve.Point(fit.knot_a) - p[1]).norm(), 1e-9);
    EXPECT_LT((curve.Point(fit.knot_b) - p[2]).norm(), 1e-9);
    EXPECT_LT((curve.Point(1) - p[3]).norm(), 1e-12);
    // End derivatives: along the given tangents, as long as the estimated
    // arc of the end chord over its parameter interval.
    const double arc0 = ApproximateArcLength((p[1] - p[0]).norm(), options.chord_height_mm);
    const double arc2 = ApproximateArcLength((p[3] - p[2]).norm(), options.chord_height_mm);
    EXPECT_LT((curve.Evaluate(0, 1)[1] - arc0 / fit.knot_a * t[0]).norm(), 1e-9);
    EXPECT_LT((curve.Evaluate(1, 1)[1] - arc2 / (1 - fit.knot_b) * t[3]).norm(), 1e-9);
  }
}

TEST(FitWindowTest, BezierSpansAreTheSameCurveAsTheBSpline) {
  const Helix helix{5.0, 1.0};
  std::array<Eigen::Vector3d, 4> p, t;
  Window(helix, {0.0, 0.7, 1.0, 1.9}, &p, &t);
  WindowFit fit;
  ASSERT_TRUE(FitWindow(p, t, LocalFitOptions(), 0, &fit).ok());
  const BSplineCurve curve = AsCurve(fit);
  const auto spans = fit.Spans();
  const double start[3] = {0, fit.knot_a, fit.knot_b}, end[3] = {fit.knot_a, fit.knot_b, 1};
  for (int k = 0; k < 3; ++k) {
    for (double x : {0.0, 0.2, 0.5, 0.9, 1.0}) {
      const double u = start[k] + x * (end[k] - start[k]);
      EXPECT_LT((spans[k].Point(x) - curve.Point(u)).norm(), 1e-10) << k << " " << x;
      const Eigen::Vector3d du = curve.Evaluate(u, 1)[1] * (end[k] - start[k]);
      EXPECT_LT((spans[k].Derivative(x) - du).norm(), 1e-9) << k << " " << x;
    }
  }
}

TEST(FitWindowTest, ReproducesAStraightLine) {
  const Eigen::Vector3d origin(1, 2, 3), dir = Eigen::Vector3d(1, -2, 2).normalized();
  const std::array<Eigen::Vector3d, 4> p = {origin, origin + 0.3 * dir, origin + 1.0 * dir,
                                            origin + 1.2 * dir};
  const std::array<Eigen::Vector3d, 4> t = {dir, dir, dir, dir};
  LocalFitOptions options;
  options.chord_height = ChordHeight::kFromNeighbours;  // sagitta 0 on a line
  WindowFit fit;
  ASSERT_TRUE(FitWindow(p, t, options, 0, &fit).ok());
  // The approximate arc of a line is the chord: parameters are arc length.
  EXPECT_NEAR(fit.knot_a, 0.25, 1e-12);
  EXPECT_NEAR(fit.knot_b, 1.0 / 1.2, 1e-12);
  const auto spans = fit.Spans();
  const double width[3] = {fit.knot_a, fit.knot_b - fit.knot_a, 1 - fit.knot_b};
  for (int k = 0; k < 3; ++k) {
    for (double x : {0.1, 0.5, 0.8}) {
      const Eigen::Vector3d q = spans[k].Point(x) - origin;
      EXPECT_LT((q - q.dot(dir) * dir).norm(), 1e-12);
      // Unit speed in arc length: |dC/du| is the total length, 1.2 mm, so
      // |dC/dx| on a span is 1.2 mm times its knot interval.
      EXPECT_NEAR(spans[k].Derivative(x).norm(), 1.2 * width[k], 1e-12);
    }
  }
}

// Max distance from the circle to the kept middle span, by sampling the
// span densely and measuring each sample's distance to the circle (exact).
double MiddleSpanErrorOnCircle(double radius, const std::array<double, 4>& angles,
                               const LocalFitOptions& options, double* chord_error) {
  std::array<Eigen::Vector3d, 4> p, t;
  for (int k = 0; k < 4; ++k) {
    p[k] = radius * Eigen::Vector3d(std::cos(angles[k]), std::sin(angles[k]), 0);
    t[k] = Eigen::Vector3d(-std::sin(angles[k]), std::cos(angles[k]), 0);
  }
  WindowFit fit;
  EXPECT_TRUE(FitWindow(p, t, options, 0, &fit).ok());
  const CubicSpan span = fit.MiddleSpan(p[1], p[2]);
  double worst = 0.0;
  for (int i = 0; i <= 200; ++i) {
    const Eigen::Vector3d q = span.Point(i / 200.0);
    worst = std::max(worst, std::hypot(std::hypot(q.x(), q.y()) - radius, q.z()));
  }
  const double half = 0.5 * (angles[2] - angles[1]);
  *chord_error = radius * (1 - std::cos(half));
  return worst;
}

TEST(FitWindowTest, CutsTheChordErrorOnACircleByOrdersOfMagnitude) {
  // The seed's pencil conditions: 0.4 mm steps (3000 mm/min, 8 ms) on a
  // 5 mm radius.
  const double radius = 5.0, step = 0.4 / radius;
  LocalFitOptions options;
  options.chord_height = ChordHeight::kFromNeighbours;
  double chord_error = 0.0;
  const double fit_error =
      MiddleSpanErrorOnCircle(radius, {0, step, 2 * step, 3 * step}, options, &chord_error);
  EXPECT_NEAR(chord_error, 0.4 * 0.4 / (8 * radius), 1e-5);
  EXPECT_LT(fit_error, chord_error / 100) << fit_error;
}

TEST(FitWindowTest, ApproximateArcBeatsUniformOnUnevenSteps) {
  const double radius = 5.0;
  const std::array<double, 4> angles = {0.0, 0.02, 0.2, 0.22};  // short, long, short
  double chord_error = 0.0;
  LocalFitOptions arc;
  arc.chord_height = ChordHeight::kFromNeighbours;
  LocalFitOptions uniform = arc;
  uniform.parametrization = Parametrization::kUniform;
  const double arc_error = MiddleSpanErrorOnCircle(radius, angles, arc, &chord_error);
  const double uniform_error = MiddleSpanErrorOnCircle(radius, angles, uniform, &chord_error);
  EXPECT_LT(arc_error * 10, uniform_error) << arc_error << " vs " << uniform_error;
}

TEST(FitWindowTest, NearArcLengthSpeedOnACircle) {
  const double radius = 5.0, step = 0.08;
  std::array<Eigen::Vector3d, 4> p, t;
  for (int k = 0; k < 4; ++k) {
    p[k] = radius * Eigen::Vector3d(std::cos(k * step), std::sin(k * step), 0);
    t[k] = Eigen::Vector3d(-std::sin(k * step), std::cos(k * step), 0);
  }
  LocalFitOptions options;
  options.chord_height = ChordHeight::kFromNeighbours;
  WindowFit fit;
  ASSERT_TRUE(FitWindow(p, t, options, 0, &fit).ok());
  // On [0, 1] the curve covers 3 steps of arc: unit arc-length speed is
  // 3 * step * radius per unit parameter.
  const BSplineCurve curve = AsCurve(fit);
  for (double u = 0; u <= 1.0; u += 0.05) {
    EXPECT_NEAR(curve.Evaluate(u, 1)[1].norm() / (3 * step * radius), 1.0, 1e-4) << u;
  }
}

TEST(FitWindowTest, RejectsRepeatedPointsAndBadTangentsNamingTheIndex) {
  const Helix helix;
  std::array<Eigen::Vector3d, 4> p, t;
  Window(helix, {0, 1, 2, 3}, &p, &t);
  WindowFit fit;
  auto repeated = p;
  repeated[2] = repeated[1];
  Status s = FitWindow(repeated, t, LocalFitOptions(), 40, &fit);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("CL point 42"), std::string::npos) << s.message();
  auto bad_tangent = t;
  bad_tangent[3] *= 2.0;
  s = FitWindow(p, bad_tangent, LocalFitOptions(), 0, &fit);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("CL point 3"), std::string::npos) << s.message();
  auto not_finite = p;
  not_finite[0].x() = std::nan("");
  EXPECT_FALSE(FitWindow(not_finite, t, LocalFitOptions(), 0, &fit).ok());
  LocalFitOptions negative;
  negative.chord_height_mm = -1;
  std::string why;
  EXPECT_FALSE(negative.IsValid(&why));
  EXPECT_NE(why.find("chord_height_mm"), std::string::npos);
}

TEST(FitPolylineTest, SpansJoinAtEveryPointAndFollowTheHelix) {
  const Helix helix;
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> step(0.1, 0.6);
  std::vector<Eigen::Vector3d> points, tangents;
  std::vector<double> arc;
  for (double s = 0; points.size() < 40; s += step(rng)) {
    arc.push_back(s);
    points.push_back(helix.Point(s));
    tangents.push_back(helix.Tangent(s));
  }
  std::vector<CubicSpan> spans;
  ASSERT_TRUE(FitPolyline(points, tangents, LocalFitOptions(), &spans).ok());
  ASSERT_EQ(spans.size(), points.size() - 1);
  for (size_t i = 0; i < spans.size(); ++i) {
    EXPECT_EQ(spans[i].Point(0), points[i]);
    EXPECT_EQ(spans[i].Point(1), points[i + 1]);
    // Mid-span: close to the helix point half way in arc length (the
    // helix's chord error at 0.6 mm steps is 4.3 um).
    const Eigen::Vector3d mid = helix.Point(0.5 * (arc[i] + arc[i + 1]));
    EXPECT_LT((spans[i].Point(0.5) - mid).norm(), 2e-4) << i;
  }
  EXPECT_FALSE(FitPolyline({points[0], points[1], points[2]}, {tangents[0], tangents[1],
                                                                tangents[2]},
                           LocalFitOptions(), &spans)
                   .ok());
}

TEST(EstimateUnitTangentsTest, ExactOnACircleAndALine) {
  const double radius = 3.0;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> angles = {0.1, 0.15, 0.4, 0.45, 0.9, 1.0};
  for (double a : angles) points.push_back(radius * Eigen::Vector3d(std::cos(a), 0, std::sin(a)));
  std::vector<Eigen::Vector3d> tangents;
  ASSERT_TRUE(EstimateUnitTangents(points, &tangents).ok());
  for (size_t i = 0; i < angles.size(); ++i) {
    const Eigen::Vector3d truth(-std::sin(angles[i]), 0, std::cos(angles[i]));
    EXPECT_LT((tangents[i] - truth).norm(), 1e-12) << i;
  }
  const Eigen::Vector3d dir = Eigen::Vector3d(3, 4, 0) / 5;
  ASSERT_TRUE(EstimateUnitTangents({dir, 2 * dir, 5 * dir}, &tangents).ok());
  for (const auto& t : tangents) EXPECT_LT((t - dir).norm(), 1e-12);
  const Status s = EstimateUnitTangents({dir, dir, 2 * dir}, &tangents);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("CL point 1"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace tpopt
