#include "model/geometry/parametric_surface.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

namespace tpopt {

Eigen::Vector3d ParametricSurface::ToolSideNormal(const SurfaceDerivatives& d) const {
  return cutter_side_sign() * d.su.cross(d.sv).normalized();
}

double ParametricSurface::NormalCurvature(const SurfaceDerivatives& d,
                                          const Eigen::Vector3d& t) const {
  // Write t = x su + y sv (least squares: t is tangent up to round-off).
  Eigen::Matrix<double, 3, 2> jac;
  jac << d.su, d.sv;
  const Eigen::Vector2d xy = jac.colPivHouseholderQr().solve(t);
  const Eigen::Vector3d n = ToolSideNormal(d);
  const double second = xy.x() * xy.x() * d.suu.dot(n) + 2 * xy.x() * xy.y() * d.suv.dot(n) +
                        xy.y() * xy.y() * d.svv.dot(n);
  return second / (jac * xy).squaredNorm();
}

PrincipalCurvatures ParametricSurface::Curvatures(const SurfaceDerivatives& d) const {
  // Shape operator W = I^-1 II; its eigenvalues are the principal
  // curvatures and its eigenvectors (in (u, v)) their directions.
  const Eigen::Vector3d n = ToolSideNormal(d);
  Eigen::Matrix2d first, second;
  first << d.su.dot(d.su), d.su.dot(d.sv), d.su.dot(d.sv), d.sv.dot(d.sv);
  second << d.suu.dot(n), d.suv.dot(n), d.suv.dot(n), d.svv.dot(n);
  // Symmetric generalised problem II x = k I x.
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(second, first);
  Eigen::Matrix<double, 3, 2> jac;
  jac << d.su, d.sv;
  PrincipalCurvatures c;
  c.k_min = solver.eigenvalues()(0);
  c.k_max = solver.eigenvalues()(1);
  c.dir_min = (jac * solver.eigenvectors().col(0)).normalized();
  c.dir_max = (jac * solver.eigenvectors().col(1)).normalized();
  return c;
}

}  // namespace tpopt
