#include "model/geometry/bspline_surface.h"

#include <algorithm>
#include <sstream>

#include <glog/logging.h>

#include "model/geometry/bspline_basis.h"

namespace tpopt {

Eigen::Vector3d SurfacePoint::UnitNormal() const {
  const Eigen::Vector3d n = du.cross(dv);
  if (!(n.norm() > 1e-12 * du.norm() * dv.norm())) return Eigen::Vector3d::Zero();
  return n.normalized();
}

Status BSplineSurface::Create(int degree_u, int degree_v, std::vector<double> knots_u,
                              std::vector<double> knots_v,
                              std::vector<std::vector<Eigen::Vector3d>> control_points,
                              const std::string& what, BSplineSurface* surface) {
  CHECK(surface != nullptr);
  std::ostringstream err;
  for (int degree : {degree_u, degree_v}) {
    if (degree < 1 || degree > kMaxDegree) {
      err << what << ": degree " << degree << " is outside [1, " << kMaxDegree << "]";
      return Status::Error(err.str());
    }
  }
  const size_t rows = control_points.size();
  const size_t cols = rows == 0 ? 0 : control_points[0].size();
  for (size_t i = 0; i < rows; ++i) {
    if (control_points[i].size() != cols) {
      err << what << ": control_points[" << i << "] has " << control_points[i].size()
          << " points, but control_points[0] has " << cols;
      return Status::Error(err.str());
    }
  }
  RETURN_IF_ERROR(NormalizeClampedKnots(degree_u, rows, what + ": knots_u", &knots_u));
  RETURN_IF_ERROR(NormalizeClampedKnots(degree_v, cols, what + ": knots_v", &knots_v));
  std::vector<Eigen::Vector3d> net;
  net.reserve(rows * cols);
  for (size_t i = 0; i < rows; ++i) {
    for (size_t j = 0; j < cols; ++j) {
      if (!control_points[i][j].allFinite()) {
        err << what << ": control_points[" << i << "][" << j << "] is not finite";
        return Status::Error(err.str());
      }
      net.push_back(control_points[i][j]);
    }
  }
  surface->degree_u_ = degree_u;
  surface->degree_v_ = degree_v;
  surface->rows_ = static_cast<int>(rows);
  surface->cols_ = static_cast<int>(cols);
  surface->knots_u_ = std::move(knots_u);
  surface->knots_v_ = std::move(knots_v);
  surface->net_ = std::move(net);
  return Status::Ok();
}

SurfacePoint BSplineSurface::Evaluate(double u, double v) const {
  CHECK(!net_.empty()) << "Evaluate on an empty surface";
  u = std::clamp(u, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0);
  const int p = degree_u_, q = degree_v_;
  const int span_u = FindKnotSpan(knots_u_, p, rows_, u);
  const int span_v = FindKnotSpan(knots_v_, q, cols_, v);
  BasisDerivatives nu, nv;
  ComputeBasisDerivatives(knots_u_, p, span_u, u, 2, nu);
  ComputeBasisDerivatives(knots_v_, q, span_v, v, 2, nv);
  // Contract along v first: row_k[i] = d^k/dv^k of the curve in row i.
  Eigen::Vector3d row[3][kMaxDegree + 1];
  for (int i = 0; i <= p; ++i) {
    for (int k = 0; k < 3; ++k) row[k][i].setZero();
    for (int j = 0; j <= q; ++j) {
      const Eigen::Vector3d& c = control_point(span_u - p + i, span_v - q + j);
      for (int k = 0; k < 3; ++k) row[k][i] += nv[k][j] * c;
    }
  }
  SurfacePoint out;
  out.point.setZero();
  out.du.setZero();
  out.dv.setZero();
  out.duu.setZero();
  out.duv.setZero();
  out.dvv.setZero();
  for (int i = 0; i <= p; ++i) {
    out.point += nu[0][i] * row[0][i];
    out.du += nu[1][i] * row[0][i];
    out.duu += nu[2][i] * row[0][i];
    out.dv += nu[0][i] * row[1][i];
    out.duv += nu[1][i] * row[1][i];
    out.dvv += nu[0][i] * row[2][i];
  }
  return out;
}

}  // namespace tpopt
