// Keeps the machine's linear joints inside their travel during the solve.
//
// The tip and axis are free in W, and a pose far from the table's centre
// maps to joints that move by the distance times the turn of A or C, so a
// solve can carry a pose out of the travel with nothing in the cost
// noticing (README, "Figures behind the defaults"). For each joint X, Y, Z (machine frame,
// through the kinematics) with travel [lo, hi] and a margin e inside it,
//   r_j = s * (max(0, J_j - (hi - e)) + max(0, (lo + e) - J_j)) / e
// zero inside the travel less e, one-sided, dimensionless; s = sqrt(w h / L)
// as in the other families, w large (a wall). A is bounded directly on its
// parameter (ceres_smoother.cc); C is unwrapped and judged after the solve.
#ifndef TPOPT_SOLVER_TRAVEL_COST_H_
#define TPOPT_SOLVER_TRAVEL_COST_H_

#include <ceres/ceres.h>

#include <array>
#include <cmath>

#include "model/machine/machine.h"
#include "solver/smooth/cost/pose_parameters.h"

namespace tpopt {

class TravelCost {
 public:
  // lo, hi: travel of X, Y, Z in mm (infinite for none); margin_mm: e > 0.
  TravelCost(const KinematicParams& kinematics, const std::array<double, 3>& lo,
             const std::array<double, 3>& hi, double margin_mm, double scale)
      : kinematics_(kinematics),
        lo_(lo),
        hi_(hi),
        margin_mm_(margin_mm),
        scale_(scale) {}

  template <typename T>
  bool operator()(const T* const pose, T* r) const {
    const Eigen::Matrix<T, 5, 1> joints = PoseJoints(kinematics_, pose);
    for (int j = 0; j < 3; ++j) {
      r[j] = T(0.0);
      if (std::isfinite(hi_[j]) && joints[j] > T(hi_[j] - margin_mm_)) {
        r[j] = T(scale_ / margin_mm_) * (joints[j] - T(hi_[j] - margin_mm_));
      } else if (std::isfinite(lo_[j]) && joints[j] < T(lo_[j] + margin_mm_)) {
        r[j] = T(scale_ / margin_mm_) * (T(lo_[j] + margin_mm_) - joints[j]);
      }
    }
    return true;
  }

  static ceres::CostFunction* Create(const KinematicParams& kinematics,
                                     const std::array<double, 3>& lo,
                                     const std::array<double, 3>& hi,
                                     double margin_mm, double scale) {
    return new ceres::AutoDiffCostFunction<TravelCost, 3, kPoseSize>(
        new TravelCost(kinematics, lo, hi, margin_mm, scale));
  }

 private:
  KinematicParams kinematics_;
  std::array<double, 3> lo_, hi_;
  double margin_mm_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_TRAVEL_COST_H_
