#include "model/geometry/freeform_surface.h"

#include <utility>

namespace tpopt {

Status FreeformSurface::Create(std::string name, std::vector<double> knots_u,
                               std::vector<double> knots_v,
                               const std::vector<std::vector<Eigen::Vector3d>>& control_points,
                               double cutter_side_sign, const std::string& what,
                               FreeformSurface* surface) {
  constexpr int kDegree = 3;
  FreeformSurface result;
  RETURN_IF_ERROR(BSplineSurface::Create(kDegree, kDegree, std::move(knots_u), std::move(knots_v),
                                         control_points, what, &result.surface_));
  result.name_ = std::move(name);
  result.side_sign_ = cutter_side_sign < 0 ? -1.0 : 1.0;
  *surface = std::move(result);
  return Status::Ok();
}

SurfaceDerivatives FreeformSurface::Evaluate(double u, double v) const {
  const SurfacePoint s = surface_.Evaluate(u, v);
  SurfaceDerivatives d;
  d.p = s.point;
  d.su = s.du;
  d.sv = s.dv;
  d.suu = s.duu;
  d.suv = s.duv;
  d.svv = s.dvv;
  return d;
}

}  // namespace tpopt
