// A clamped NURBS (rational B-spline) curve as CAM systems write it for
// spline motion (NX CLSF NURBS/ with KNOT/ and CNTRL/ records), turned into
// points that straight moves follow within a chord tolerance.
#ifndef TPOPT_MODEL_RATIONAL_CURVE_H_
#define TPOPT_MODEL_RATIONAL_CURVE_H_

#include <Eigen/Core>
#include <string>
#include <vector>

#include "model/base/status.h"

namespace tpopt {

struct RationalCurve {
  int degree = 3;
  // knots.size() == control_points.size() + degree + 1, clamped, any range.
  std::vector<double> knots;
  // mm.
  std::vector<Eigen::Vector3d> control_points;
  // One weight (> 0) a control point; empty means all 1 (non-rational).
  std::vector<double> weights;
};

// Points along `curve` from just after its start to its end point (last),
// so that the chords between them stay within `chord_tolerance_mm` (> 0)
// of the curve (checked at the quarter, half and three-quarter parameter of
// each chord; spans are bisected until they are). Errors (degree, counts,
// knots, weights) are prefixed with `what` (file:line).
Status RationalCurvePoints(const RationalCurve& curve, double chord_tolerance_mm,
                           const std::string& what, std::vector<Eigen::Vector3d>* points);

// The curve's point at the parameter t in [0, 1] (the knot range mapped to
// [0, 1]); `curve` must be valid (RationalCurvePoints accepts it).
Eigen::Vector3d RationalCurvePoint(const RationalCurve& curve, double t);

}  // namespace tpopt

#endif  // TPOPT_MODEL_RATIONAL_CURVE_H_
