// Smoothness of the path: the k-th derivative (k = 2 or 3) over arc length
// of A, C and the tool tip, from k + 1 consecutive poses.
//
// Cost (per family, over the whole path):
//   E_k = w_angle (1/L) integral |(A, C)^(k)(s)|^2 ds
//       + w_tip   (1/L) integral |p_w_tip^(k)(s)|^2 ds
// with L the path length. The discrete form is a sum over stencils with the
// stencil's mean step h = (s_k - s_0) / k standing for ds, and the derivative
// from divided differences (solver/smooth/cost/divided_difference.h), so
//   r_angle = sqrt(w_angle h / L) * sum_j c_j (A_j, C_j)        [rad/mm^k]
//   r_tip   = sqrt(w_tip h / L)   * sum_j c_j p_j               [mm/mm^k]
// With reference angles (A, C)_ref per pose (the rulings' own,
// solver/smooth/ruling_angles.h), r_angle differentiates (A, C) - (A, C)_ref
// instead. A and C may weigh differently (w_angle = (w_A, w_C)): near the
// pole A may have its reference where C has none. Neither the point density
// nor the path length changes what a weight means. Units: w_angle in
// mm^(2k)/rad^2, w_tip in mm^(2k-2), so that E_k is dimensionless like the
// deviation cost. The cost is linear in the poses.
#ifndef TPOPT_SOLVER_SMOOTHNESS_COST_H_
#define TPOPT_SOLVER_SMOOTHNESS_COST_H_

#include <array>
#include <cmath>

#include <ceres/ceres.h>

#include "solver/smooth/cost/divided_difference.h"
#include "solver/smooth/cost/pose_parameters.h"
#include "solver/smooth/cost/pose_stencil.h"

namespace tpopt {

template <int kOrder>
class SmoothnessCost : public PoseStencil<SmoothnessCost<kOrder>> {
 public:
  static_assert(kOrder == 2 || kOrder == 3, "second or third derivative");

  // Reference (A, C) per pose, radians: the angles' departure from it is
  // what is differentiated (zero: the angles themselves).
  using Reference = std::array<std::array<double, 2>, kOrder + 1>;

  // s_mm: arc-length abscissae of the k + 1 poses; path_length_mm: L.
  SmoothnessCost(const std::array<double, kOrder + 1>& s_mm, double path_length_mm,
                 const std::array<double, 2>& w_angle, double w_tip,
                 const Reference& reference = {})
      : weights_(DerivativeWeights<kOrder>(s_mm)) {
    reference_sum_ = {0.0, 0.0};
    for (int j = 0; j <= kOrder; ++j) {
      for (int d = 0; d < 2; ++d) reference_sum_[d] += weights_[j] * reference[j][d];
    }
    const double h = (s_mm[kOrder] - s_mm[0]) / kOrder;
    for (int d = 0; d < 2; ++d) angle_scale_[d] = std::sqrt(w_angle[d] * h / path_length_mm);
    tip_scale_ = std::sqrt(w_tip * h / path_length_mm);
  }

  static ceres::CostFunction* Create(const std::array<double, kOrder + 1>& s_mm,
                                     double path_length_mm, double w_angle, double w_tip,
                                     const Reference& reference = {}) {
    return Create(s_mm, path_length_mm, {w_angle, w_angle}, w_tip, reference);
  }

  static ceres::CostFunction* Create(const std::array<double, kOrder + 1>& s_mm,
                                     double path_length_mm, const std::array<double, 2>& w_angle,
                                     double w_tip, const Reference& reference = {}) {
    auto* functor = new SmoothnessCost(s_mm, path_length_mm, w_angle, w_tip, reference);
    if constexpr (kOrder == 2) {
      return new ceres::AutoDiffCostFunction<SmoothnessCost, kPoseSize, kPoseSize, kPoseSize,
                                             kPoseSize>(functor);
    } else {
      return new ceres::AutoDiffCostFunction<SmoothnessCost, kPoseSize, kPoseSize, kPoseSize,
                                             kPoseSize, kPoseSize>(functor);
    }
  }

  // Residuals from the k + 1 poses (PoseStencil calls this).
  template <typename T>
  bool Evaluate(const T* const* poses, T* r) const {
    for (int d = 0; d < kPoseSize; ++d) {
      T sum(0.0);
      for (int j = 0; j <= kOrder; ++j) sum += weights_[j] * poses[j][d];
      r[d] = d < kPoseTip ? angle_scale_[d] * (sum - reference_sum_[d]) : tip_scale_ * sum;
    }
    return true;
  }

 private:
  std::array<double, kOrder + 1> weights_;
  std::array<double, 2> reference_sum_;
  std::array<double, 2> angle_scale_ = {0.0, 0.0};
  double tip_scale_ = 0.0;
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SMOOTHNESS_COST_H_
