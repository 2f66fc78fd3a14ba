#include "solver/smooth/resample.h"

#include <cmath>
#include <sstream>

#include "model/base/invalid_field.h"
#include "solver/spline/pose_spline.h"

namespace tpopt {
namespace {

// Resamples poses [first, end) of `in` (one cutting run) into `out`.
Status ResampleRun(const ToolPath& in, const std::vector<JointVector>& joints, size_t first,
                   size_t end, double step_mm, ToolPath* out) {
  const size_t n = end - first;
  if (n < 3) {
    out->poses.insert(out->poses.end(), in.poses.begin() + first, in.poses.begin() + end);
    return Status::Ok();
  }
  // Arc length with repeated poses dropped (a spline needs increasing s).
  std::vector<size_t> kept = {first};
  std::vector<double> s = {0.0};
  for (size_t i = first + 1; i < end; ++i) {
    const double ds = (in.poses[i].p_w_tip - in.poses[kept.back()].p_w_tip).norm();
    if (ds < 1e-9) continue;
    kept.push_back(i);
    s.push_back(s.back() + ds);
  }
  if (kept.size() < 3) {
    out->poses.insert(out->poses.end(), in.poses.begin() + first, in.poses.begin() + end);
    return Status::Ok();
  }
  PoseSpline fit;
  RETURN_IF_ERROR(PoseSpline::Fit(in, joints, kept, s, PoseSpline::Ends::kNatural, &fit));
  const int steps = std::max(1, static_cast<int>(std::ceil(s.back() / step_mm - 1e-9)));
  size_t source = 0;  // the kept pose at or after the sample, for its feed
  for (int j = 0; j <= steps; ++j) {
    const double sj = s.back() * j / steps;
    while (source + 1 < kept.size() && s[source] < sj - 1e-12) ++source;
    ToolPose p = in.poses[kept[source]];
    if (j == 0) p = in.poses[first];
    if (j == steps) p = in.poses[kept.back()];
    if (j > 0 && j < steps) {
      p = Derived(p);
      fit.Evaluate(sj, &p);
    }
    out->poses.push_back(p);
  }
  return Status::Ok();
}

}  // namespace

bool ResampleOptions::IsValid(std::string* why) const {
  if (step_mm > 0 && std::isfinite(step_mm)) return true;
  if (why != nullptr) *why = InvalidField("--resample_step_mm", step_mm, "finite and > 0");
  return false;
}

Status ResamplePath(const ToolPath& in, const Machine& machine, const ResampleOptions& options,
                    ToolPath* out) {
  std::string why;
  if (!options.IsValid(&why)) return Status::Error(why);
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(in, &joints));
  ToolPath result = WithoutPoses(in);
  for (size_t first = 0; first < in.poses.size();) {
    const size_t end = RunEnd(in, first);
    RETURN_IF_ERROR(ResampleRun(in, joints, first, end, options.step_mm, &result));
    first = end;
  }
  *out = std::move(result);
  return Status::Ok();
}

}  // namespace tpopt
