#include "model/geometry/surface_projection.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tpopt {
namespace {

constexpr double kConvergedMm = 1e-9;
constexpr double kMissMm = 1e-6;
constexpr int kGrid = 40;

// Two unit vectors completing `direction` to an orthonormal frame.
void PerpendicularBasis(const Eigen::Vector3d& direction, Eigen::Vector3d* e1,
                        Eigen::Vector3d* e2) {
  const Eigen::Vector3d helper = std::abs(direction.x()) < 0.9 ? Eigen::Vector3d::UnitX()
                                                                : Eigen::Vector3d::UnitY();
  *e1 = direction.cross(helper).normalized();
  *e2 = direction.cross(*e1);
}

struct Residual {
  Eigen::Vector2d f;
  Eigen::Matrix2d jacobian;
};

Residual Evaluate(const BSplineSurface& surface, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Eigen::Vector2d& uv) {
  const SurfacePoint sp = surface.Evaluate(uv.x(), uv.y());
  const Eigen::Vector3d d = sp.point - origin;
  Residual r;
  r.f << d.dot(e1), d.dot(e2);
  r.jacobian << sp.du.dot(e1), sp.dv.dot(e1), sp.du.dot(e2), sp.dv.dot(e2);
  return r;
}

// Damped Newton from uv; returns the residual norm reached, mm.
double Newton(const BSplineSurface& surface, const Eigen::Vector3d& origin,
              const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, Eigen::Vector2d* uv) {
  Residual r = Evaluate(surface, origin, e1, e2, *uv);
  double norm = r.f.norm();
  for (int iteration = 0; iteration < 30 && norm > kConvergedMm; ++iteration) {
    const double det = r.jacobian.determinant();
    if (!(std::abs(det) > 1e-300)) break;
    const Eigen::Vector2d step = -r.jacobian.inverse() * r.f;
    bool improved = false;
    // Halve the step until the residual falls: a full step can leave the
    // square or overshoot where the surface bends.
    for (double scale = 1.0; scale > 1e-4; scale *= 0.5) {
      const Eigen::Vector2d trial = (*uv + scale * step).cwiseMax(0.0).cwiseMin(1.0);
      const Residual rt = Evaluate(surface, origin, e1, e2, trial);
      if (rt.f.norm() < norm) {
        *uv = trial;
        r = rt;
        norm = rt.f.norm();
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  return norm;
}

Eigen::Vector2d GridStart(const BSplineSurface& surface, const Eigen::Vector3d& origin,
                          const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  Eigen::Vector2d best(0.5, 0.5);
  double best_norm = INFINITY;
  for (int i = 0; i <= kGrid; ++i) {
    for (int j = 0; j <= kGrid; ++j) {
      const Eigen::Vector2d uv(double(i) / kGrid, double(j) / kGrid);
      const Eigen::Vector3d d = surface.Point(uv.x(), uv.y()) - origin;
      const double norm = std::hypot(d.dot(e1), d.dot(e2));
      if (norm < best_norm) {
        best_norm = norm;
        best = uv;
      }
    }
  }
  return best;
}

}  // namespace

Status ProjectAlongDirection(const BSplineSurface& surface, const Eigen::Vector3d& origin,
                             const Eigen::Vector3d& unit_direction, const Eigen::Vector2d* guess,
                             SurfaceHit* hit) {
  Eigen::Vector3d e1, e2;
  PerpendicularBasis(unit_direction, &e1, &e2);
  Eigen::Vector2d uv = guess != nullptr ? guess->cwiseMax(0.0).cwiseMin(1.0)
                                        : GridStart(surface, origin, e1, e2);
  double residual = Newton(surface, origin, e1, e2, &uv);
  if (residual > kConvergedMm && guess != nullptr) {
    uv = GridStart(surface, origin, e1, e2);
    residual = Newton(surface, origin, e1, e2, &uv);
  }
  if (!(residual <= kMissMm)) {
    std::ostringstream err;
    err << "the line through (" << origin.transpose() << ") along (" << unit_direction.transpose()
        << ") misses the surface (nearest approach " << residual << " mm)";
    return Status::Error(err.str());
  }
  hit->u = uv.x();
  hit->v = uv.y();
  hit->point = surface.Point(uv.x(), uv.y());
  hit->distance_mm = (hit->point - origin).dot(unit_direction);
  return Status::Ok();
}

}  // namespace tpopt
