// Removes the gauge freedom of the flank distance: sliding the tip along its
// own axis changes no flank distance, so the tip is held where the input had
// it relative to the floor of the cut (its contact point on rail 0). The
// tool's axial position is the programmer's choice: CAM writes flank paths
// with the tip 1-3 mm below the bottom rail so that the whole ruling is cut
// by the flute, and a gauge pulling every tip up to the rail moves the tool
// by that much along an axis that points far from the table's centre,
// enough to leave the travel. With h0 the input's overhang there (the
// median over its cutting run, model/path/rail_projection.h RunOverhangs),
//   h0 = median over the run of (C1(u_j) - p_in_j) . a_in_j         [mm]
//   h  = (C1(u_i) - p_w_tip) . a_w                                  [mm]
//   r  = sqrt(w h_s / L) * (h - h0) / tol
// with h_s the arc-length step of the pose and L the path length, as in the
// other families; w is dimensionless.
#ifndef TPOPT_SOLVER_TIP_HEIGHT_COST_H_
#define TPOPT_SOLVER_TIP_HEIGHT_COST_H_

#include <ceres/ceres.h>

#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class TipHeightCost {
 public:
  // contact_w: C1(u_i) in W; height_mm: h0, the input's height of the
  // floor above its tip along its axis; scale = sqrt(w h_s / L) / tol.
  TipHeightCost(const Eigen::Vector3d& contact_w, double height_mm, double scale)
      : contact_w_(contact_w), height_mm_(height_mm), scale_(scale) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    r[0] = T(scale_) * ((contact_w_.cast<T>() - PoseTip(pose)).dot(PoseAxis(pose)) - height_mm_);
    return true;
  }

  static ceres::CostFunction* Create(const Eigen::Vector3d& contact_w, double height_mm,
                                     double scale) {
    return new ceres::AutoDiffCostFunction<TipHeightCost, 1, kPoseSize>(
        new TipHeightCost(contact_w, height_mm, scale));
  }

 private:
  Eigen::Vector3d contact_w_;
  double height_mm_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TIP_HEIGHT_COST_H_
