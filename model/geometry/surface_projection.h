// Projection of a point onto a B-spline surface along a fixed direction:
// the intersection of the line origin + t * direction with S(u, v).
#ifndef TPOPT_MODEL_SURFACE_PROJECTION_H_
#define TPOPT_MODEL_SURFACE_PROJECTION_H_

#include <Eigen/Core>

#include "model/geometry/bspline_surface.h"
#include "model/base/status.h"

namespace tpopt {

struct SurfaceHit {
  double u = 0.0, v = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // S(u, v), mm
  double distance_mm = 0.0;  // t along the direction from the origin (may be < 0)
};

// Newton's method on (u, v) for the two components of S(u, v) - origin
// normal to `unit_direction`, started at `guess` (the previous point's
// parameters along a curve), with steps halved until the residual falls and
// (u, v) kept in the unit square. When that does not converge to 1e-9 mm,
// a 41 x 41 grid search picks a new start (the robust fallback, also used
// when `guess` is null). Fails when the line misses the surface (the
// nearest approach is farther than 1e-6 mm) or the surface is singular
// there; the message gives the origin and direction.
Status ProjectAlongDirection(const BSplineSurface& surface, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& unit_direction, const Eigen::Vector2d* guess,
                             SurfaceHit* hit);

}  // namespace tpopt

#endif  // TPOPT_MODEL_SURFACE_PROJECTION_H_
