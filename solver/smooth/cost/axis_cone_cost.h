// Keeps a pose's tool axis within a cone round its starting axis.
//
// The flank distance does not change when the axis turns about its contact
// line, so on a strongly twisted surface the deviation family alone lets an
// axis swing far from the CAM's (README, "Figures behind the defaults").
// With a0 the input's axis and theta the cone's half angle,
//   c = 1 - a_w . a0                      (1 - cos of the angle between them)
//   r = s * max(0, c - (1 - cos theta)) / (1 - cos theta)
// a one-sided wall, zero inside the cone, dimensionless; s = sqrt(w h / L)
// as in the other families, w dimensionless and large (a wall, not a
// trade-off). 1 - a . a0 rather than the angle itself: it is smooth at
// a = a0 and needs no acos.
#ifndef TPOPT_SOLVER_AXIS_CONE_COST_H_
#define TPOPT_SOLVER_AXIS_CONE_COST_H_

#include <ceres/ceres.h>

#include <cmath>

#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class AxisConeCost {
 public:
  // a0_w: unit starting axis in W; cone_rad: half angle, (0, pi); scale: s.
  AxisConeCost(const Eigen::Vector3d& a0_w, double cone_rad, double scale)
      : a0_w_(a0_w), wall_(1.0 - std::cos(cone_rad)), scale_(scale) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    const T excess = T(1.0) - PoseAxis(pose).dot(a0_w_.cast<T>()) - T(wall_);
    r[0] = excess > T(0.0) ? T(scale_ / wall_) * excess : T(0.0);
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& a0_w,
                                     double cone_rad, double scale) {
    return new ceres::AutoDiffCostFunction<AxisConeCost, 1, kPoseSize>(
        new AxisConeCost(a0_w, cone_rad, scale));
  }

 private:
  Eigen::Vector3d a0_w_;
  double wall_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_AXIS_CONE_COST_H_
