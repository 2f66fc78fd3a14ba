// One-sided cap on the second derivative of A and C over the tip's travel,
// measured by the judge's own SecondDifferenceOverTravel
// (model/machine/axis_metrics.h) from three consecutive poses:
//   D = |(q_2 - q_1) / ds_1 - (q_1 - q_0) / ds_0| / ((ds_0 + ds_1) / 2)
// with ds_j = |tip_{j+1} - tip_j| of the poses being solved, and
//   r_q = sqrt(w h / L) * max(0, D - cap_q) / cap_q
// for q = A, C (no residual where cap_q is 0). The quadratic smoothness
// families weigh every stencil alike, so a path held to the tolerance at a
// few points keeps its peaks there unless the whole path is stiffened; this
// family is zero below the cap and acts on the peaks alone, the way the
// tolerance points act on the deviation (issue 16: peak d2 <= 2 x the clean
// SPO path's). h is the stencil's mean step along s and L the path length,
// as in the other families; w is dimensionless.
#ifndef TPOPT_SOLVER_PEAK_SECOND_COST_H_
#define TPOPT_SOLVER_PEAK_SECOND_COST_H_

#include <ceres/ceres.h>

#include <array>
#include <cmath>

#include "model/machine/axis_metrics.h"
#include "solver/smooth/cost/pose_parameters.h"
#include "solver/smooth/cost/pose_stencil.h"

namespace tpopt {

class PeakSecondCost : public PoseStencil<PeakSecondCost> {
 public:
  // cap_per_mm2: the cap on |d2A/ds2| and |d2C/ds2|, rad/mm^2 (0: none).
  PeakSecondCost(const std::array<double, 2>& cap_per_mm2, double scale)
      : cap_(cap_per_mm2), scale_(scale) {}

  static ceres::CostFunction* Create(const std::array<double, 2>& cap_per_mm2, double scale) {
    constexpr int P = kPoseSize;
    return new ceres::AutoDiffCostFunction<PeakSecondCost, 2, P, P, P>(
        new PeakSecondCost(cap_per_mm2, scale));
  }

  // Residuals from the three poses (PoseStencil calls this).
  template <typename T>
  bool Evaluate(const T* const* poses, T* r) const {
    const T ds0 = (PoseTip(poses[1]) - PoseTip(poses[0])).norm();
    const T ds1 = (PoseTip(poses[2]) - PoseTip(poses[1])).norm();
    for (int q = 0; q < 2; ++q) {
      r[q] = T(0.0);
      // A stencil whose tips stand (a repeated pose) has no slope to bend.
      if (cap_[q] <= 0 || !(ds0 > T(kMinStepMm) && ds1 > T(kMinStepMm))) continue;
      const int d = q == 0 ? kPoseA : kPoseC;
      const T excess =
          SecondDifferenceOverTravel(poses[0][d], poses[1][d], poses[2][d], ds0, ds1) - T(cap_[q]);
      if (excess > T(0.0)) r[q] = T(scale_ / cap_[q]) * excess;
    }
    return true;
  }

 private:
  static constexpr double kMinStepMm = 1e-6;
  std::array<double, 2> cap_;
  double scale_;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_PEAK_SECOND_COST_H_
