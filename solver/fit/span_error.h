// How well pieces between CL points follow the ideal CL curve: the chord
// error of straight segments against the error of fitted cubic spans, and
// the tangent mismatch where fitted spans meet.
#ifndef TPOPT_SOLVER_SPAN_ERROR_H_
#define TPOPT_SOLVER_SPAN_ERROR_H_

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "solver/fit/bspline_fit.h"

namespace tpopt {

// Distance from q to curve(t), t in [lo, hi], mm: the best of 33 samples,
// refined by a golden-section search on the bracket around it (the
// distance is unimodal there for the short pieces of a tool path).
double DistanceToCurve(const std::function<Eigen::Vector3d(double)>& curve, double lo, double hi,
                       const Eigen::Vector3d& q);

// DistanceToCurve over a cubic span's [0, 1].
double DistanceToSpan(const CubicSpan& span, const Eigen::Vector3d& q);

struct SpanErrors {
  double max_chord_error_mm = 0.0;  // ideal curve to straight segments
  double max_fit_error_mm = 0.0;    // ideal curve to fitted spans
  double max_join_angle_deg = 0.0;  // between a span's end and the next's start
  size_t worst_fit_span = 0;
};

// The ideal curve between points i and i + 1 at fraction x in (0, 1) of its
// own parameter there.
using IdealCurve = std::function<Eigen::Vector3d(size_t i, double x)>;

// Measures `spans` (spans[i] from points[i] to points[i + 1]) at
// `samples_per_span` interior samples of the ideal curve each.
SpanErrors MeasureSpanErrors(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<CubicSpan>& spans, const IdealCurve& ideal,
                             int samples_per_span);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SPAN_ERROR_H_
