// A clamped, non-rational B-spline curve in R^3 of any degree.
//
// The knot vector given by the file may span any range; it is mapped affinely
// to [0, 1] so that every curve in tpopt is parametrised on [0, 1].
#ifndef TPOPT_MODEL_BSPLINE_CURVE_H_
#define TPOPT_MODEL_BSPLINE_CURVE_H_

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "model/geometry/bspline_basis.h"
#include "model/base/status.h"

namespace tpopt {

class BSplineCurve {
 public:
  BSplineCurve() = default;

  // Highest degree accepted; evaluation uses fixed-size stack buffers.
  static constexpr int kMaxDegree = kMaxBSplineDegree;

  // Validates and builds a curve. Requirements: 1 <= degree <= kMaxDegree;
  // knots.size() == control_points.size() + degree + 1; knots finite and
  // non-decreasing with a non-empty range; clamped (first and last knots
  // repeated degree + 1 times); control points finite. `what` names the
  // curve in error messages (e.g. "surface.json: rails[1]").
  static Status Create(int degree, std::vector<double> knots,
                       std::vector<Eigen::Vector3d> control_points,
                       const std::string& what, BSplineCurve* curve);

  int degree() const { return degree_; }
  // Knots after mapping to [0, 1].
  const std::vector<double>& knots() const { return knots_; }
  const std::vector<Eigen::Vector3d>& control_points() const {
    return control_points_;
  }

  // Point and derivatives d^k C / du^k for k = 0..max_order (max_order <= 3)
  // at u in [0, 1] (clamped), from the basis-function derivatives (Piegl &
  // Tiller, algorithm A2.3); orders above the degree are zero. Units: mm / (unit parameter)^k.
  std::array<Eigen::Vector3d, 4> Evaluate(double u, int max_order) const;
  Eigen::Vector3d Point(double u) const { return Evaluate(u, 0)[0]; }

  // Radius of curvature |C'|^3 / |C' x C''| in mm; +infinity where straight.
  double CurvatureRadius(double u) const;

 private:
  int degree_ = 0;
  std::vector<double> knots_;
  std::vector<Eigen::Vector3d> control_points_;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_BSPLINE_CURVE_H_
