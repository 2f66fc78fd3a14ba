#include "model/geometry/bspline_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <glog/logging.h>

namespace tpopt {

Status BSplineCurve::Create(int degree, std::vector<double> knots,
                            std::vector<Eigen::Vector3d> control_points,
                            const std::string& what, BSplineCurve* curve) {
  CHECK(curve != nullptr);
  RETURN_IF_ERROR(NormalizeClampedKnots(degree, control_points.size(), what, &knots));
  for (size_t i = 0; i < control_points.size(); ++i) {
    if (!control_points[i].allFinite()) {
      std::ostringstream err;
      err << what << ": control point " << i << " is not finite";
      return Status::Error(err.str());
    }
  }
  curve->degree_ = degree;
  curve->knots_ = std::move(knots);
  curve->control_points_ = std::move(control_points);
  return Status::Ok();
}

std::array<Eigen::Vector3d, 4> BSplineCurve::Evaluate(double u, int max_order) const {
  CHECK(!control_points_.empty()) << "Evaluate on an empty curve";
  CHECK(max_order >= 0 && max_order <= 3);
  u = std::clamp(u, 0.0, 1.0);
  const int p = degree_;
  const int span =
      FindKnotSpan(knots_, p, static_cast<int>(control_points_.size()), u);
  BasisDerivatives ders;
  ComputeBasisDerivatives(knots_, p, span, u, max_order, ders);
  std::array<Eigen::Vector3d, 4> out;
  for (auto& v : out) v.setZero();
  for (int k = 0; k <= std::min(max_order, p); ++k) {
    for (int j = 0; j <= p; ++j) {
      out[k] += ders[k][j] * control_points_[span - p + j];
    }
  }
  return out;
}

double BSplineCurve::CurvatureRadius(double u) const {
  const auto d = Evaluate(u, 2);
  const double speed = d[1].norm();
  const double cross = d[1].cross(d[2]).norm();
  if (cross <= 1e-14 * speed * speed * speed) {
    return std::numeric_limits<double>::infinity();
  }
  return speed * speed * speed / cross;
}

}  // namespace tpopt
