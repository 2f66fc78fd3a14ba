// Surface-free smoothing (what commercial CAM calls tool-axis smoothing):
// without a surface, a pose may move only within a band around what the
// program already does. For pose i with original tip p0, unit tangent t of
// the original tip polyline at p0 and original axis a0:
//   d_perp = |(p - p0) - ((p - p0) . t) t|              distance off the polyline [mm]
//   c      = 1 - a . a0                                  1 - cos(angle to a0)
//   r_tip   = s * max(0, d_perp - m tol) / tol
//   r_axis  = s * max(0, c - (1 - cos(m tol_a))) / (1 - cos(tol_a))
//   r_slide = s * slide * ((p - p0) . t) / h
// with s = sqrt(w h / L) as in the other families, m < 1 a margin, h the
// arc-length step of the pose. The walls are soft, so under the smoothing's
// pull a pose ends slightly past its wall; m = 0.98 leaves room for that
// before the final clamp, which moves a pose without its neighbours, has to
// act, yet hands the smoothing all but 2 % of the promised band (README,
// "Figures behind the defaults"). The first two are one-sided walls, zero
// inside the band; the third, weak, keeps a pose at its station along the
// path so that smoothing cannot bunch poses up. 1 - a . a0 is used rather
// than the angle itself because it is smooth at a = a0.
#ifndef TPOPT_SOLVER_TOLERANCE_BAND_COST_H_
#define TPOPT_SOLVER_TOLERANCE_BAND_COST_H_

#include <cmath>

#include <ceres/ceres.h>

#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class ToleranceBandCost {
 public:
  struct Band {
    Eigen::Vector3d p0_w, tangent_w, a0_w;
    double tolerance_mm = 0.01;
    double angle_tolerance_rad = 0.5 * M_PI / 180;
    double margin = 0.98;  // m above
    double step_mm = 1.0;
  };

  ToleranceBandCost(const Band& band, double scale, double slide_weight)
      : band_(band), scale_(scale), slide_weight_(slide_weight) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    const Eigen::Matrix<T, 3, 1> d = PoseTip(pose) - band_.p0_w.cast<T>();
    const T along = d.dot(band_.tangent_w.cast<T>());
    const Eigen::Matrix<T, 3, 1> perp = d - along * band_.tangent_w.cast<T>();
    const T perp2 = perp.squaredNorm();
    using std::sqrt;
    const T d_perp = perp2 > T(1e-24) ? T(sqrt(perp2)) : T(0.0);
    const T tip_excess = d_perp - T(band_.margin * band_.tolerance_mm);
    r[0] = tip_excess > T(0.0) ? T(scale_ / band_.tolerance_mm) * tip_excess : T(0.0);
    const double cos_unit = 1.0 - std::cos(band_.angle_tolerance_rad);
    const double cos_wall = 1.0 - std::cos(band_.margin * band_.angle_tolerance_rad);
    const T c = T(1.0) - PoseAxis(pose).dot(band_.a0_w.cast<T>());
    const T axis_excess = c - T(cos_wall);
    r[1] = axis_excess > T(0.0) ? T(scale_ / cos_unit) * axis_excess : T(0.0);
    r[2] = T(scale_ * slide_weight_ / band_.step_mm) * along;
    return true;
  }

  static ceres::CostFunction* Create(const Band& band, double scale, double slide_weight) {
    return new ceres::AutoDiffCostFunction<ToleranceBandCost, 3, kPoseSize>(
        new ToleranceBandCost(band, scale, slide_weight));
  }

 private:
  Band band_;
  double scale_;
  double slide_weight_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TOLERANCE_BAND_COST_H_
