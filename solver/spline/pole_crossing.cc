#include "solver/spline/pole_crossing.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "model/machine/machine.h"

namespace tpopt {
namespace {

// The horizontal unit vector of azimuth c (A = 90 deg on the machine).
Eigen::Vector3d Horizontal(double c_rad) {
  return AnglesToAxis<double>(M_PI / 2, c_rad);
}

}  // namespace

PoleCrossing FitPoleCrossing(const ToolPath& path, const PolePassage& passage) {
  // The line through the origin nearest (least squares) to the points
  // xy_i is the principal axis of their second moment sum xy_i xy_i^T; not
  // of their covariance, since the line must pass through the pole.
  Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
  for (size_t i = passage.first; i <= passage.last; ++i) {
    const Eigen::Vector2d xy = path.poses[i].a_w.head<2>();
    moment += xy * xy.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(moment);
  Eigen::Vector3d along(eigen.eigenvectors()(0, 1), eigen.eigenvectors()(1, 1),
                        0.0);
  // Face the way the passage comes in, so that C is held at the value the
  // path arrives with rather than half a turn from it.
  if (along.dot(path.poses[passage.first].a_w) < 0) along = -along;

  PoleCrossing crossing;
  crossing.passage = passage;
  crossing.plane_c_rad = AxisToAngles(along)[0][1];
  const Eigen::Vector3d normal = Horizontal(crossing.plane_c_rad + M_PI / 2);
  for (size_t i = passage.first; i <= passage.last; ++i) {
    const double off_plane = std::abs(normal.dot(path.poses[i].a_w));
    crossing.miss_rad =
        std::max(crossing.miss_rad, std::asin(std::min(1.0, off_plane)));
  }
  return crossing;
}

void RouteThroughPole(const PoleCrossing& crossing, ToolPath* path) {
  const Eigen::Vector3d along = Horizontal(crossing.plane_c_rad);
  for (size_t i = crossing.passage.first; i <= crossing.passage.last; ++i) {
    Eigen::Vector3d& a_w = path->poses[i].a_w;
    // Without its normal component the axis is (a.along) along + a_z z,
    // which is AnglesToAxis(A, plane C) scaled, with A the signed tilt
    // towards `along`.
    const double tilt_rad = std::atan2(along.dot(a_w), a_w.z());
    a_w = AnglesToAxis(tilt_rad, crossing.plane_c_rad);
  }
}

}  // namespace tpopt
