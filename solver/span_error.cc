#include "solver/span_error.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

namespace tpopt {

double DistanceToSegment(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         const Eigen::Vector3d& q) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

double DistanceToSpan(const CubicSpan& span, const Eigen::Vector3d& q) {
  constexpr int kSamples = 32;
  int best = 0;
  double best_d2 = INFINITY;
  for (int i = 0; i <= kSamples; ++i) {
    const double d2 = (span.Point(double(i) / kSamples) - q).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  double lo = std::max(0, best - 1) / double(kSamples);
  double hi = std::min(kSamples, best + 1) / double(kSamples);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  auto d2_at = [&](double t) { return (span.Point(t) - q).squaredNorm(); };
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double f1 = d2_at(x1), f2 = d2_at(x2);
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - golden * (hi - lo);
      f1 = d2_at(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + golden * (hi - lo);
      f2 = d2_at(x2);
    }
  }
  return std::sqrt(std::min({best_d2, f1, f2}));
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
          std::max(errors.max_chord_error_mm, DistanceToSegment(points[i], points[i + 1], q));
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
