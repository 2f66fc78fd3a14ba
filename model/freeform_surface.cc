#include "model/freeform_surface.h"

#include <utility>

#include <glog/logging.h>

namespace tpopt {

Status FreeformSurface::Create(std::string name, std::vector<double> knots_u,
                               std::vector<double> knots_v,
                               const std::vector<std::vector<Eigen::Vector3d>>& control_points,
                               double cutter_side_sign, const std::string& what,
                               FreeformSurface* surface) {
  constexpr int kDegree = 3;
  const size_t rows = control_points.size();
  if (rows < kDegree + 1) {
    return Status::Error(what + ": control_points needs at least 4 rows (along u), got " +
                         std::to_string(rows));
  }
  const size_t cols = control_points[0].size();
  for (size_t i = 0; i < rows; ++i) {
    if (control_points[i].size() != cols) {
      return Status::Error(what + ": control_points[" + std::to_string(i) + "] has " +
                           std::to_string(control_points[i].size()) + " points, row 0 has " +
                           std::to_string(cols));
    }
  }
  // The u-knots are checked by building a throw-away curve over the first
  // column, which applies the same rules as the rows' v-knots.
  std::vector<Eigen::Vector3d> column(rows);
  for (size_t i = 0; i < rows; ++i) column[i] = control_points[i][0];
  BSplineCurve u_curve;
  Status s = BSplineCurve::Create(kDegree, std::move(knots_u), column, what + ": knots_u", &u_curve);
  if (!s.ok()) return s;
  FreeformSurface result;
  result.rows_.resize(rows);
  for (size_t i = 0; i < rows; ++i) {
    s = BSplineCurve::Create(kDegree, knots_v, control_points[i],
                             what + ": knots_v / control_points[" + std::to_string(i) + "]",
                             &result.rows_[i]);
    if (!s.ok()) return s;
  }
  result.name_ = std::move(name);
  result.knots_u_ = u_curve.knots();
  result.side_sign_ = cutter_side_sign < 0 ? -1.0 : 1.0;
  *surface = std::move(result);
  return Status::Ok();
}

SurfaceDerivatives FreeformSurface::Evaluate(double u, double v) const {
  // S(u, v) = sum_i N_i(u) R_i(v): the rows R_i evaluated at v (with their
  // v-derivatives) are the control points of cubic curves in u.
  const size_t rows = rows_.size();
  std::vector<Eigen::Vector3d> pts[3];
  for (auto& p : pts) p.resize(rows);
  for (size_t i = 0; i < rows; ++i) {
    const auto r = rows_[i].Evaluate(v, 2);
    for (int k = 0; k < 3; ++k) pts[k][i] = r[k];
  }
  std::array<Eigen::Vector3d, 4> along_u[3];
  for (int k = 0; k < 3; ++k) {
    BSplineCurve curve;
    // Knots and points are already valid (checked in Create).
    const Status s = BSplineCurve::Create(3, knots_u_, std::move(pts[k]), "surface row", &curve);
    CHECK(s.ok()) << s.message();
    along_u[k] = curve.Evaluate(u, 2 - k);
  }
  SurfaceDerivatives d;
  d.p = along_u[0][0];
  d.su = along_u[0][1];
  d.suu = along_u[0][2];
  d.sv = along_u[1][0];
  d.suv = along_u[1][1];
  d.svv = along_u[2][0];
  return d;
}

}  // namespace tpopt
