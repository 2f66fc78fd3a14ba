// A smooth parametric surface S(u, v), (u, v) in [0, 1]^2, in the workpiece
// frame W, seen through its point and partial derivatives up to order two.
// The strip-width code (model/eval/strip_width.h) works on any such surface: the
// bicubic FreeformSurface, and in tests closed-form spheres and cylinders.
#ifndef TPOPT_MODEL_PARAMETRIC_SURFACE_H_
#define TPOPT_MODEL_PARAMETRIC_SURFACE_H_

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tpopt {

// Point and partials at one (u, v): mm and mm per unit parameter^k.
struct SurfaceDerivatives {
  Eigen::Vector3d p, su, sv, suu, suv, svv;
};

// Principal curvatures (1/mm) with respect to the tool-side normal:
// positive where the surface bends towards the tool (concave, as seen by
// the cutter), negative where it bends away (convex). k_max >= k_min.
struct PrincipalCurvatures {
  double k_max = 0.0, k_min = 0.0;
  Eigen::Vector3d dir_max = Eigen::Vector3d::Zero();  // unit, tangent
  Eigen::Vector3d dir_min = Eigen::Vector3d::Zero();
};

class ParametricSurface {
 public:
  virtual ~ParametricSurface() = default;
  // (u, v) are clamped to [0, 1].
  virtual SurfaceDerivatives Evaluate(double u, double v) const = 0;
  // +1 when the cutter lies on the side of su x sv, -1 on the other side.
  virtual double cutter_side_sign() const = 0;

  // Unit normal pointing towards the cutter. Precondition: su x sv != 0.
  Eigen::Vector3d ToolSideNormal(const SurfaceDerivatives& d) const;
  // Normal curvature (1/mm) in the tangent direction `t` (any length),
  // signed as PrincipalCurvatures: II(t, t) / I(t, t) against the tool-side
  // normal, from the first and second fundamental forms.
  double NormalCurvature(const SurfaceDerivatives& d, const Eigen::Vector3d& t) const;
  PrincipalCurvatures Curvatures(const SurfaceDerivatives& d) const;
};

}  // namespace tpopt

#endif  // TPOPT_MODEL_PARAMETRIC_SURFACE_H_
