#include "solver/pose_spline.h"

namespace tpopt {

Status PoseSpline::Fit(const ToolPath& path, const std::vector<JointVector>& joints,
                       const std::vector<size_t>& indices, const std::vector<double>& s,
                       PoseSpline* out) {
  for (int k = 0; k < 5; ++k) {
    std::vector<double> y;
    y.reserve(indices.size());
    for (size_t i : indices) y.push_back(k < 3 ? path.poses[i].p_w_tip[k] : joints[i][k]);
    RETURN_IF_ERROR(SmoothingSpline::Fit(s, y, {}, 0.0, &out->fit_[k]));
  }
  return Status::Ok();
}

void PoseSpline::Evaluate(double s, ToolPose* pose) const {
  pose->p_w_tip = Eigen::Vector3d(fit_[kX](s), fit_[kY](s), fit_[kZ](s));
  pose->a_w = AnglesToAxis(fit_[kA](s), fit_[kC](s));
}

}  // namespace tpopt
