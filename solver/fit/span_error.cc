#include "solver/fit/span_error.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

#include "model/geometry/segment_distance.h"

namespace tpopt {

double DistanceToCurve(const std::function<Eigen::Vector3d(double)>& curve, double lo, double hi,
                       const Eigen::Vector3d& q) {
  constexpr int kSamples = 32;
  auto at = [&](int i) { return lo + (hi - lo) * i / kSamples; };
  auto d2_at = [&](double t) { return (curve(t) - q).squaredNorm(); };
  int best = 0;
  double best_d2 = INFINITY;
  for (int i = 0; i <= kSamples; ++i) {
    const double d2 = d2_at(at(i));
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  double a = at(std::max(0, best - 1)), b = at(std::min(kSamples, best + 1));
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
  double f1 = d2_at(x1), f2 = d2_at(x2);
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (f1 < f2) {
      b = x2;
      x2 = x1;
      f2 = f1;
      x1 = b - golden * (b - a);
      f1 = d2_at(x1);
    } else {
      a = x1;
      x1 = x2;
      f1 = f2;
      x2 = a + golden * (b - a);
      f2 = d2_at(x2);
    }
  }
  return std::sqrt(std::min({best_d2, f1, f2}));
}

double DistanceToSpan(const CubicSpan& span, const Eigen::Vector3d& q) {
  return DistanceToCurve([&span](double t) { return span.Point(t); }, 0.0, 1.0, q);
}

SpanErrors MeasureSpanErrors(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<CubicSpan>& spans, const IdealCurve& ideal,
                             int samples_per_span) {
  CHECK_EQ(spans.size() + 1, points.size());
  SpanErrors errors;
  for (size_t i = 0; i < spans.size(); ++i) {
    for (int k = 1; k <= samples_per_span; ++k) {
      const Eigen::Vector3d q = ideal(i, double(k) / (samples_per_span + 1));
      errors.max_chord_error_mm =
          std::max(errors.max_chord_error_mm, DistanceToSegment(q, points[i], points[i + 1]));
      const double fit = DistanceToSpan(spans[i], q);
      if (fit > errors.max_fit_error_mm) {
        errors.max_fit_error_mm = fit;
        errors.worst_fit_span = i;
      }
    }
    if (i > 0) {
      const Eigen::Vector3d before = spans[i - 1].Derivative(1.0), after = spans[i].Derivative(0.0);
      const double angle = std::atan2(before.cross(after).norm(), before.dot(after));
      errors.max_join_angle_deg = std::max(errors.max_join_angle_deg, angle * 180.0 / M_PI);
    }
  }
  return errors;
}

}  // namespace tpopt
