#include "solver/spline/pose_spline.h"

#include <algorithm>

namespace tpopt {

std::vector<double> TipArcLength(const ToolPose* poses, size_t n, const ArcLengthStepFloor& floor) {
  std::vector<double> s(n, 0.0);
  if (n < 2) return s;
  double floor_mm = floor.min_step_mm;
  if (floor.of_mean_step != 0.0) {
    double total = 0.0;
    for (size_t i = 1; i < n; ++i) total += (poses[i].p_w_tip - poses[i - 1].p_w_tip).norm();
    floor_mm = std::max(floor_mm, floor.of_mean_step * total / static_cast<double>(n - 1));
  }
  for (size_t i = 1; i < n; ++i) {
    s[i] = s[i - 1] + std::max(floor_mm, (poses[i].p_w_tip - poses[i - 1].p_w_tip).norm());
  }
  return s;
}

Status PoseSpline::Fit(const ToolPath& path, const std::vector<JointVector>& joints,
                       const std::vector<size_t>& indices, const std::vector<double>& s, Ends ends,
                       PoseSpline* out) {
  for (int k = 0; k < 5; ++k) {
    std::vector<double> y;
    y.reserve(indices.size());
    for (size_t i : indices) y.push_back(k < 3 ? path.poses[i].p_w_tip[k] : joints[i][k]);
    RETURN_IF_ERROR(ends == Ends::kNatural
                        ? SmoothingSpline::Fit(s, y, {}, 0.0, &out->fit_[k])
                        : SmoothingSpline::InterpolateNotAKnot(s, y, &out->fit_[k]));
  }
  return Status::Ok();
}

void PoseSpline::Evaluate(double s, ToolPose* pose) const {
  pose->p_w_tip = Eigen::Vector3d(fit_[kX](s), fit_[kY](s), fit_[kZ](s));
  pose->a_w = AnglesToAxis(fit_[kA](s), fit_[kC](s));
}

}  // namespace tpopt
