#include "model/machine/planner_time.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/machine/axis_metrics.h"
#include "model/base/invalid_field.h"
#include "model/base/units.h"

namespace tpopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// What a speed change from v1 to v2 at tangential acceleration a costs over
// an instant change: the ramp takes |v1 - v2| / a and covers the distance
// (v1^2 - v2^2) / (2a), which the faster speed would cover in that distance
// over v_high. From or to rest (v = 0) it is v / (2a).
double RampCost(double v1, double v2, double a) {
  const double high = std::max(v1, v2);
  if (!std::isfinite(a) || !(a > 0) || !(high > 0)) return 0.0;
  const double dv = v1 - v2;
  return dv * dv / (2.0 * a * high);
}

}  // namespace

bool PlannerOptions::IsValid(std::string* why) const {
  std::string problem;
  if (!(blend_acceleration_fraction > 0 && blend_acceleration_fraction <= 1)) {
    problem = InvalidField("blend_acceleration_fraction", blend_acceleration_fraction, "in (0, 1]");
  } else if (!(default_feed_mm_per_min > 0) || !std::isfinite(default_feed_mm_per_min)) {
    problem = InvalidField("--feed", default_feed_mm_per_min, "finite and > 0 mm/min");
  }
  if (why != nullptr) *why = problem;
  return problem.empty();
}

namespace {

// PlanMove for a caller that has the move's SegmentTime, dt_s, already.
PlannerMove PlanMoveTaking(double dt_s, const Machine& machine, const ToolPath& path,
                           const std::vector<JointVector>& joints, size_t i,
                           const PlannerOptions& options) {
  CHECK_LT(i + 1, path.poses.size());
  PlannerMove move;
  const Eigen::Vector3d dp = path.poses[i + 1].p_w_tip - path.poses[i].p_w_tip;
  const JointVector dj = joints[i + 1] - joints[i];
  // Components in axis units (mm, rad) and the path length they scale with.
  const double d[5] = {dp.x(), dp.y(), dp.z(), dj[kA], dj[kC]};
  const double tip_mm = dp.norm();
  move.rotary_only = !(tip_mm > 1e-9);
  move.length = move.rotary_only
                    ? std::max(std::abs(dj[kA]), std::abs(dj[kC])) * kRadToDeg
                    : tip_mm;
  move.requested_speed = dt_s > 0 ? move.length / dt_s : kInf;
  double v_move = kInf;
  double a_move = kInf;
  for (int k = 0; k < 5; ++k) {
    if (std::abs(d[k]) <= 1e-12 || move.length <= 0) continue;
    const double ratio =
        std::abs(d[k]) / move.length;  // axis units per path unit
    const AxisLimits& lim = machine.limits[k];
    if (std::isfinite(lim.max_velocity))
      v_move = std::min(v_move, lim.max_velocity / ratio);
    if (std::isfinite(lim.max_acceleration)) {
      a_move = std::min(a_move, lim.max_acceleration / ratio);
    }
  }
  move.tangential_acceleration = options.blend_acceleration_fraction * a_move;
  move.axis_speed = v_move;
  move.triangle_speed = std::sqrt(move.tangential_acceleration * move.length);
  move.max_speed = std::min(move.axis_speed, move.triangle_speed);
  move.speed = std::min(move.requested_speed, move.max_speed);
  return move;
}

}  // namespace

PlannerMove PlanMove(const Machine& machine, const ToolPath& path,
                     const std::vector<JointVector>& joints, size_t i,
                     const PlannerOptions& options) {
  CHECK_LT(i + 1, path.poses.size());
  return PlanMoveTaking(SegmentTime(machine, path, joints, i, options.default_feed_mm_per_min),
                        machine, path, joints, i, options);
}

PlannerTime PredictPlannerTime(const Machine& machine, const ToolPath& path,
                               const std::vector<JointVector>& joints,
                               const PlannerOptions& options) {
  CHECK_EQ(joints.size(), path.poses.size());
  std::string why;
  CHECK(options.IsValid(&why)) << why;
  PlannerTime out;
  const size_t n = path.poses.size();
  bool previous_feed = false;
  PlannerMove previous;
  for (size_t i = 0; i + 1 < n; ++i) {
    const double dt_s =
        SegmentTime(machine, path, joints, i, options.default_feed_mm_per_min);
    const bool feed = !path.poses[i + 1].rapid && dt_s > 0;
    if (!feed) {
      if (previous_feed)
        out.ramp_time_s +=
            RampCost(previous.speed, 0.0, previous.tangential_acceleration);
      out.time_s += dt_s;
      previous_feed = false;
      continue;
    }
    const PlannerMove move = PlanMoveTaking(dt_s, machine, path, joints, i, options);
    out.time_s += move.speed > 0 ? move.length / move.speed : dt_s;
    out.capped_moves += move.speed < move.requested_speed * (1 - 1e-9);
    if (previous_feed && previous.rotary_only == move.rotary_only) {
      const PlannerMove& faster =
          previous.speed >= move.speed ? previous : move;
      out.ramp_time_s +=
          RampCost(previous.speed, move.speed, faster.tangential_acceleration);
    } else {
      // From rest, and where the path unit changes, as a stop in between.
      if (previous_feed) {
        out.ramp_time_s +=
            RampCost(previous.speed, 0.0, previous.tangential_acceleration);
      }
      out.ramp_time_s +=
          RampCost(0.0, move.speed, move.tangential_acceleration);
    }
    previous = move;
    previous_feed = true;
  }
  if (previous_feed)
    out.ramp_time_s +=
        RampCost(previous.speed, 0.0, previous.tangential_acceleration);
  out.time_s += out.ramp_time_s;
  return out;
}

}  // namespace tpopt
