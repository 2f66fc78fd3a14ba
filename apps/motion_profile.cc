#include "apps/motion_profile.h"

#include <cmath>
#include <limits>

#include "model/machine/axis_metrics.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<int, 2> kRotaries = {kA, kC};

}  // namespace

Status ComputeMotionProfile(const Machine& machine, const ToolPath& path,
                            double default_feed_mm_per_min, MotionProfile* profile) {
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
  const MotionSamples m = ComputeMotionSamples(machine, path, joints, default_feed_mm_per_min);
  MotionProfile out;
  const size_t n = joints.size();
  out.s_pose_mm.assign(n, 0.0);
  for (size_t i = 0; i + 1 < n; ++i) {
    out.s_pose_mm[i + 1] = out.s_pose_mm[i] + m.ds_mm[i];
    out.s_segment_mm.push_back(out.s_pose_mm[i] + 0.5 * m.ds_mm[i]);
  }
  for (int k = 0; k < 2; ++k) {
    const int axis = kRotaries[k];
    for (size_t i = 0; i < n; ++i) {
      out.angle_deg[k].push_back(joints[i][axis] * kRadToDeg);
      out.acceleration_deg_s2[k].push_back(
          m.has_acceleration[i] ? m.acceleration[i][axis] * kRadToDeg : kGap);
    }
    for (size_t i = 0; i + 1 < n; ++i) {
      out.velocity_deg_s[k].push_back(m.cutting[i] ? m.velocity[i][axis] * kRadToDeg : kGap);
    }
  }
  *profile = std::move(out);
  return Status::Ok();
}

}  // namespace tpopt
