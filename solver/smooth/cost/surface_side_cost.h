// Keeps the tool axis on the cutter's side of the surface.
//
// A cylinder whose axis lies R on the far side of a ruling touches that
// ruling as well as one on the near side, and one lying across the surface
// touches it along a line: the flank distance cannot tell them apart, and a
// solve that drifts there gouges by the cutter radius. For the ends of the
// pose's ruling q_k = C_k(u_i) (k = 1, 2) with n_k the unit surface normal
// there on the cutter side, the point of the axis level with q_k is
//   x_k = p_w_tip + ((q_k - p_w_tip) . a_w) a_w
// and its height over the surface's tangent plane is
//   d_k = (x_k - q_k) . n_k                                         [mm]
// which is about R(h_k) (the cutter's radius at that height) on a flank pose
// and negative once the axis is on the wrong side. The wall
//   r_k = s * max(0, m R_k - d_k) / R_k,    m = 1/2
// is zero for any pose the deviation family would accept and grows long
// before the axis reaches the surface; dimensionless, s = sqrt(w h / L) as
// in the other families, w large (a wall). R_k is fixed at the input's
// height, as the gauge (tip_height_cost.h) holds that.
#ifndef TPOPT_SOLVER_SURFACE_SIDE_COST_H_
#define TPOPT_SOLVER_SURFACE_SIDE_COST_H_

#include <ceres/ceres.h>

#include <array>

#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class SurfaceSideCost {
 public:
  struct End {
    Eigen::Vector3d q_w;       // C_k(u_i), the end of the ruling
    Eigen::Vector3d normal_w;  // unit normal there, towards the cutter
    double radius_mm = 4.0;    // the cutter's radius level with q_w, > 0
  };
  static constexpr double kMargin = 0.5;  // m above

  SurfaceSideCost(const std::array<End, 2>& ends, double scale)
      : ends_(ends), scale_(scale) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    const Eigen::Matrix<T, 3, 1> p = PoseTip(pose);
    const Eigen::Matrix<T, 3, 1> a = PoseAxis(pose);
    for (int k = 0; k < 2; ++k) {
      const Eigen::Matrix<T, 3, 1> q = ends_[k].q_w.cast<T>();
      const Eigen::Matrix<T, 3, 1> x = p + (q - p).dot(a) * a;
      const T d = (x - q).dot(ends_[k].normal_w.cast<T>());
      const T shortfall = T(kMargin * ends_[k].radius_mm) - d;
      r[k] = shortfall > T(0.0) ? T(scale_ / ends_[k].radius_mm) * shortfall
                                : T(0.0);
    }
    return true;
  }

  static ceres::CostFunction* Create(const std::array<End, 2>& ends,
                                     double scale) {
    return new ceres::AutoDiffCostFunction<SurfaceSideCost, 2, kPoseSize>(
        new SurfaceSideCost(ends, scale));
  }

 private:
  std::array<End, 2> ends_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SURFACE_SIDE_COST_H_
