// The rotary axes' motion along a path, sample by sample, for plotting:
// angle, velocity and acceleration of A and C against the tip's path length.
#ifndef TPOPT_APPS_MOTION_PROFILE_H_
#define TPOPT_APPS_MOTION_PROFILE_H_

#include <array>
#include <vector>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

// Index 0 is A, 1 is C. Degrees, per s, per s^2. Samples where a quantity
// does not exist (the velocity of a rapid, the acceleration next to one)
// are NaN, which the plots draw as gaps.
struct MotionProfile {
  std::vector<double> s_pose_mm;     // tip path length at each pose
  std::vector<double> s_segment_mm;  // at the middle of each move
  std::array<std::vector<double>, 2> angle_deg;         // per pose
  std::array<std::vector<double>, 2> velocity_deg_s;    // per move
  std::array<std::vector<double>, 2> acceleration_deg_s2;  // per pose
};

// Joints as Machine::AssignJoints chooses them, timed as model/machine/axis_metrics.h
// times them at `default_feed_mm_per_min` where a pose has no feed. Fails as
// AssignJoints does.
Status ComputeMotionProfile(const Machine& machine, const ToolPath& path,
                            double default_feed_mm_per_min, MotionProfile* profile);

}  // namespace tpopt

#endif  // TPOPT_APPS_MOTION_PROFILE_H_
