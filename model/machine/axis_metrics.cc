#include "model/machine/axis_metrics.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

#include "model/base/invalid_field.h"
#include "model/machine/planner_time.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

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
    *why = InvalidField("--feed", default_feed_mm_per_min, "finite and > 0 mm/min");
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

MotionSamples ComputeMotionSamples(const Machine& machine, const ToolPath& path,
                                   const std::vector<JointVector>& joints,
                                   double default_feed_mm_per_min) {
  CHECK_EQ(joints.size(), path.poses.size());
  MotionSamples m;
  const size_t n = joints.size();
  const size_t segments = n > 0 ? n - 1 : 0;
  m.dt_s.assign(segments, 0.0);
  m.ds_mm.assign(segments, 0.0);
  m.cutting.assign(segments, false);
  m.velocity.assign(segments, JointVector::Zero());
  m.has_acceleration.assign(n, false);
  m.acceleration.assign(n, JointVector::Zero());
  m.has_jerk.assign(n, false);
  m.jerk.assign(n, JointVector::Zero());
  for (size_t i = 0; i < segments; ++i) {
    m.dt_s[i] = SegmentTime(machine, path, joints, i, default_feed_mm_per_min);
    m.ds_mm[i] = (path.poses[i + 1].p_w_tip - path.poses[i].p_w_tip).norm();
    m.cutting[i] = !path.poses[i + 1].rapid && m.dt_s[i] > 0;
    if (m.cutting[i]) m.velocity[i] = (joints[i + 1] - joints[i]) / m.dt_s[i];
  }
  for (size_t i = 1; i < segments; ++i) {
    if (!m.cutting[i] || !m.cutting[i - 1]) continue;
    m.has_acceleration[i] = true;
    m.acceleration[i] = (m.velocity[i] - m.velocity[i - 1]) / (0.5 * (m.dt_s[i] + m.dt_s[i - 1]));
    if (!m.has_acceleration[i - 1]) continue;
    m.has_jerk[i] = true;
    m.jerk[i] = (m.acceleration[i] - m.acceleration[i - 1]) / m.dt_s[i - 1];
  }
  return m;
}

double SecondDerivativePerMm2(const ToolPath& path, const std::vector<JointVector>& joints,
                              const MotionSamples& m, size_t i, int a) {
  if (i == 0 || i + 1 >= joints.size() || !m.has_acceleration[i]) return 0.0;
  if (path.poses[i].link || path.poses[i + 1].link) return 0.0;
  const double ds_mid = 0.5 * (m.ds_mm[i] + m.ds_mm[i - 1]);
  if (!(ds_mid > 1e-9 && m.ds_mm[i] > 1e-9 && m.ds_mm[i - 1] > 1e-9)) return 0.0;
  return SecondDifferenceOverTravel(joints[i - 1][a], joints[i][a], joints[i + 1][a],
                                    m.ds_mm[i - 1], m.ds_mm[i]);
}

MotionReport EvaluateMotion(const Machine& machine, const ToolPath& path,
                            const std::vector<JointVector>& joints,
                            const MotionOptions& options) {
  MotionReport report;
  double worst_excess = 0.0;
  const size_t n = joints.size();
  // Travel.
  for (size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 5; ++a) {
      if (!machine.limits[a].InTravel(joints[i][a])) {
        Flag(a, static_cast<int>(i), 1.0, &report, &worst_excess);
      }
    }
  }
  const MotionSamples m =
      ComputeMotionSamples(machine, path, joints, options.default_feed_mm_per_min);
  // Checks one derivative sample against its limit and keeps the peak.
  auto check = [&](int a, int pose, double value, double limit, double* peak) {
    *peak = std::max(*peak, std::abs(value));
    if (Exceeds(value, limit)) {
      Flag(a, pose, std::abs(value) / limit, &report, &worst_excess);
    }
  };
  for (size_t i = 0; i + 1 < n; ++i) {
    report.machining_time_s += m.dt_s[i];
    if (!m.cutting[i]) continue;
    report.path_length_mm += m.ds_mm[i];
    for (int a = 0; a < 5; ++a) {
      check(a, static_cast<int>(i + 1), m.velocity[i][a], machine.limits[a].max_velocity,
            &report.axes[a].peak_velocity);
    }
  }
  for (size_t i = 1; i + 1 < n; ++i) {
    if (!m.has_acceleration[i]) continue;
    for (int a = 0; a < 5; ++a) {
      AxisMotion& axis = report.axes[a];
      check(a, static_cast<int>(i), m.acceleration[i][a], machine.limits[a].max_acceleration,
            &axis.peak_acceleration);
      if (m.has_jerk[i]) {
        check(a, static_cast<int>(i), m.jerk[i][a], machine.limits[a].max_jerk, &axis.peak_jerk);
      }
      axis.peak_second_derivative_per_mm2 = std::max(axis.peak_second_derivative_per_mm2,
                                                      SecondDerivativePerMm2(path, joints, m, i, a));
    }
  }
  for (const AxisMotion& a : report.axes) report.limit_violations += a.limit_violations;
  PlannerOptions planner;
  planner.default_feed_mm_per_min = options.default_feed_mm_per_min;
  report.planner_time_s = PredictPlannerTime(machine, path, joints, planner).time_s;
  return report;
}

}  // namespace tpopt
