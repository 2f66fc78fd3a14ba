// A bicubic tensor-product B-spline surface (non-rational, clamped knots):
//   S(u, v) = sum_i sum_j N_i,3(u) N_j,3(v) P_ij,  (u, v) in [0, 1]^2,
// the file's knot ranges mapped affinely to [0, 1] as for BSplineCurve.
// The geometry is model/geometry/bspline_surface.h's; this adds what a cutter
// placement needs on top: a name, the side the cutter is on, and the
// ParametricSurface interface (normals and curvatures towards the tool).
// Its JSON file is read by model/io/freeform_surface_json.h.
#ifndef TPOPT_MODEL_FREEFORM_SURFACE_H_
#define TPOPT_MODEL_FREEFORM_SURFACE_H_

#include <string>
#include <vector>

#include <Eigen/Core>

#include "model/geometry/bspline_surface.h"
#include "model/geometry/parametric_surface.h"
#include "model/base/status.h"

namespace tpopt {

class FreeformSurface : public ParametricSurface {
 public:
  FreeformSurface() = default;

  // Validates and builds (BSplineSurface::Create with degree 3 both ways):
  // each knot vector clamped, non-decreasing, of size (control points in
  // that direction) + 4, a rectangular grid of finite points. `what` names the
  // surface in messages (e.g. the file).
  static Status Create(std::string name, std::vector<double> knots_u, std::vector<double> knots_v,
                       const std::vector<std::vector<Eigen::Vector3d>>& control_points,
                       double cutter_side_sign, const std::string& what,
                       FreeformSurface* surface);

  SurfaceDerivatives Evaluate(double u, double v) const override;
  double cutter_side_sign() const override { return side_sign_; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  BSplineSurface surface_;
  double side_sign_ = 1.0;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_FREEFORM_SURFACE_H_
