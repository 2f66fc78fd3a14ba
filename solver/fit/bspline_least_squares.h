// Global least-squares cubic B-spline fit of a whole point sequence to a
// tolerance (Piegl & Tiller, The NURBS Book, 9.4.1): the comparison the
// seed's local method is measured against. End points are interpolated;
// knots follow the data parameters by averaging (eq. 9.69); the number of
// control points is the least, by bisection, whose curve passes within the
// tolerance of every point at that point's parameter.
#ifndef TPOPT_SOLVER_BSPLINE_LEAST_SQUARES_H_
#define TPOPT_SOLVER_BSPLINE_LEAST_SQUARES_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/geometry/bspline_curve.h"
#include "model/base/status.h"
#include "solver/fit/bspline_fit.h"

namespace tpopt {

struct LeastSquaresFitOptions {
  // Data parameters; kApproximateArc uses the circle through each chord's
  // neighbours (ChordHeight::kFromNeighbours).
  Parametrization parametrization = Parametrization::kChordLength;
  double tolerance_mm = 0.001;  // > 0
  bool IsValid(std::string* why) const;
};

struct LeastSquaresFit {
  BSplineCurve curve;               // on [0, 1]
  std::vector<double> parameters;   // of the data points, in [0, 1]
  double max_error_mm = 0.0;        // at the data points' parameters
};

// Needs >= 4 points with no two consecutive ones equal (an error names the
// index). Fails when even one control point per data point (interpolation)
// misses the tolerance, which only rounding can cause.
Status FitLeastSquares(const std::vector<Eigen::Vector3d>& points,
                       const LeastSquaresFitOptions& options, LeastSquaresFit* fit);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_BSPLINE_LEAST_SQUARES_H_
