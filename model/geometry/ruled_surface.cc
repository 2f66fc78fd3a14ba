#include "model/geometry/ruled_surface.h"

#include <cmath>

#include <glog/logging.h>

namespace tpopt {

Eigen::Vector3d RuledSurface::Du(double u, double v) const {
  return (1.0 - v) * rail0_.Evaluate(u, 1)[1] + v * rail1_.Evaluate(u, 1)[1];
}

Eigen::Vector3d RuledSurface::Dv(double u) const {
  return rail1_.Point(u) - rail0_.Point(u);
}

Eigen::Vector3d RuledSurface::Normal(double u, double v) const {
  const Eigen::Vector3d n = Du(u, v).cross(Dv(u));
  const double len = n.norm();
  CHECK_GT(len, 0.0) << "degenerate normal at (u, v) = (" << u << ", " << v
                     << ")";
  return side_sign() * n / len;
}

double RuledSurface::GaussianCurvature(double u, double v) const {
  const auto c1 = rail0_.Evaluate(u, 2);
  const auto c2 = rail1_.Evaluate(u, 2);
  const Eigen::Vector3d ru = (1.0 - v) * c1[1] + v * c2[1];
  const Eigen::Vector3d rv = c2[0] - c1[0];
  const Eigen::Vector3d ruv = c2[1] - c1[1];
  const Eigen::Vector3d n = ru.cross(rv);
  const double eg_f2 = n.squaredNorm();  // |r_u x r_v|^2 = EG - F^2
  if (eg_f2 <= 0.0) return 0.0;
  const double m = ruv.dot(n) / std::sqrt(eg_f2);
  return -m * m / eg_f2;
}

}  // namespace tpopt
