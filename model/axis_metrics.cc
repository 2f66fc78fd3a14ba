#include "model/axis_metrics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

namespace tpopt {
namespace {

constexpr double kRadToDeg = 180.0 / M_PI;
// Relative slack before a sample counts as a violation, so that a path
// planned exactly at a limit is not flagged by round-off.
constexpr double kLimitSlack = 1e-6;

bool Exceeds(double value, double limit) {
  return std::abs(value) > limit * (1.0 + kLimitSlack);
}

// Records a violation on `axis` at `pose`, keeping the worst relative excess.
void Flag(int axis, int pose, double excess, MotionReport* report,
          double* worst_excess) {
  ++report->axes[axis].limit_violations;
  if (excess > *worst_excess) {
    *worst_excess = excess;
    report->worst_violation_pose = pose;
  }
}

}  // namespace

bool MotionOptions::IsValid(std::string* why) const {
  if (std::isfinite(default_feed_mm_per_min) && default_feed_mm_per_min > 0) {
    return true;
  }
  if (why != nullptr) {
    std::ostringstream err;
    err << "default feed " << default_feed_mm_per_min << " mm/min must be > 0";
    *why = err.str();
  }
  return false;
}

double SegmentTime(const Machine& machine, const ToolPath& path,
                   const std::vector<JointVector>& joints, size_t i,
                   double default_feed_mm_per_min) {
  const ToolPose& to = path.poses[i + 1];
  const JointVector dj = joints[i + 1] - joints[i];
  const double tip_mm = (to.p_w_tip - path.poses[i].p_w_tip).norm();
  if (to.rapid) {
    double t = 0.0;
    bool limited = false;
    for (int a = 0; a < 5; ++a) {
      const double v = machine.limits[a].max_velocity;
      if (std::isfinite(v) && v > 0) {
        t = std::max(t, std::abs(dj[a]) / v);
        limited = true;
      }
    }
    return limited ? t : tip_mm / (kDefaultRapidMmPerMin / 60.0);
  }
  const double feed = to.feed_mm_per_min > 0 ? to.feed_mm_per_min : default_feed_mm_per_min;
  const double speed = feed / 60.0;
  if (tip_mm > 1e-9) return tip_mm / speed;
  const double rotary_deg = std::max(std::abs(dj[kA]), std::abs(dj[kC])) * kRadToDeg;
  return rotary_deg / speed;
}

MotionReport EvaluateMotion(const Machine& machine, const ToolPath& path,
                            const std::vector<JointVector>& joints,
                            const MotionOptions& options) {
  CHECK_EQ(joints.size(), path.poses.size());
  MotionReport report;
  double worst_excess = 0.0;
  const size_t n = joints.size();
  // Travel.
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 5; ++a) {
      const AxisLimits& lim = machine.limits[a];
      if (joints[i][a] < lim.min - 1e-9 || joints[i][a] > lim.max + 1e-9) {
        Flag(a, static_cast<int>(i), 1.0, &report, &worst_excess);
      }
    }
  }
  if (n < 2) return report;
  // Segment times, lengths and velocities; feed[i] says segment i cuts.
  std::vector<double> dt(n - 1), ds(n - 1);
  std::vector<bool> feed(n - 1);
  std::vector<JointVector> vel(n - 1), dj_ds(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) {
    dt[i] = SegmentTime(machine, path, joints, i, options.default_feed_mm_per_min);
    ds[i] = (path.poses[i + 1].p_w_tip - path.poses[i].p_w_tip).norm();
    feed[i] = !path.poses[i + 1].rapid && dt[i] > 0;
    report.machining_time_s += dt[i];
    if (!feed[i]) continue;
    report.path_length_mm += ds[i];
    vel[i] = (joints[i + 1] - joints[i]) / dt[i];
    dj_ds[i] = ds[i] > 1e-9 ? JointVector((joints[i + 1] - joints[i]) / ds[i])
                            : JointVector(JointVector::Zero());
  }
  // Accelerations at the pose between segments i-1 and i.
  std::vector<JointVector> acc(n - 1, JointVector::Zero());
  std::vector<bool> has_acc(n - 1, false);
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!feed[i]) continue;
    for (int a = 0; a < 5; ++a) {
      report.axes[a].peak_velocity = std::max(report.axes[a].peak_velocity, std::abs(vel[i][a]));
      if (Exceeds(vel[i][a], machine.limits[a].max_velocity)) {
        Flag(a, static_cast<int>(i + 1), std::abs(vel[i][a]) / machine.limits[a].max_velocity,
             &report, &worst_excess);
      }
    }
    if (i == 0 || !feed[i - 1]) continue;
    has_acc[i] = true;
    acc[i] = (vel[i] - vel[i - 1]) / (0.5 * (dt[i] + dt[i - 1]));
    const double ds_mid = 0.5 * (ds[i] + ds[i - 1]);
    for (int a = 0; a < 5; ++a) {
      AxisMotion& m = report.axes[a];
      m.peak_acceleration = std::max(m.peak_acceleration, std::abs(acc[i][a]));
      if (ds_mid > 1e-9) {
        m.peak_second_derivative_per_mm2 = std::max(
            m.peak_second_derivative_per_mm2, std::abs(dj_ds[i][a] - dj_ds[i - 1][a]) / ds_mid);
      }
      if (Exceeds(acc[i][a], machine.limits[a].max_acceleration)) {
        Flag(a, static_cast<int>(i), std::abs(acc[i][a]) / machine.limits[a].max_acceleration,
             &report, &worst_excess);
      }
    }
    if (!has_acc[i - 1]) continue;
    const JointVector jerk = (acc[i] - acc[i - 1]) / dt[i - 1];
    for (int a = 0; a < 5; ++a) {
      report.axes[a].peak_jerk = std::max(report.axes[a].peak_jerk, std::abs(jerk[a]));
      if (Exceeds(jerk[a], machine.limits[a].max_jerk)) {
        Flag(a, static_cast<int>(i), std::abs(jerk[a]) / machine.limits[a].max_jerk, &report,
             &worst_excess);
      }
    }
  }
  for (const AxisMotion& m : report.axes) report.limit_violations += m.limit_violations;
  return report;
}

}  // namespace tpopt
