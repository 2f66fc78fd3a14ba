// Time of a path on a blending trajectory planner such as LinuxCNC's: what
// the plain timing model of model/machine/axis_metrics.h (every move at its feed)
// leaves out.
//
// Each feed move is a straight line in the planner's coordinates, taken as
// the tip in W for X, Y, Z (TCP convention, as axis_metrics times moves) and
// the A, C joints. Like LinuxCNC's interpreter, the planner gives a move of
// path length L with components d_k the speed and acceleration that keep
// every axis within its limits, v_move = min_k v_k L / |d_k| and
// a_move = min_k a_k L / |d_k|; while blending it uses a fraction of
// a_move along the path (LinuxCNC: half, the rest is kept for the blend),
// a_t = blend_acceleration_fraction * a_move. Then:
//  - a move cannot run faster than it can reach and leave again within its
//    own length, sqrt(a_t L) (the triangle profile), nor faster than v_move:
//    its speed is v = min(feed, v_move, sqrt(a_t L));
//  - where the speed changes from v1 to v2 between neighbouring feed moves,
//    the planner ramps at a_t (of the move the ramp lies in: the faster
//    one), which takes |v1 - v2| / a_t and costs (v1 - v2)^2 / (2 a_t v_high)
//    over the instant change; a run starts from and ends at rest.
// Rapids keep axis_metrics's time. Path length is mm for a move of the tip,
// degrees for a rotary-only move (as LinuxCNC reads F for those).
#ifndef TPOPT_MODEL_PLANNER_TIME_H_
#define TPOPT_MODEL_PLANNER_TIME_H_

#include <string>
#include <vector>

#include "model/machine/machine.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct PlannerOptions {
  // Fraction of a move's acceleration the planner uses along the path. (0, 1].
  double blend_acceleration_fraction = 0.5;
  // Feed where a pose has none, mm/min. > 0.
  double default_feed_mm_per_min = 1000.0;
  bool IsValid(std::string* why) const;
};

// One feed move as the planner sees it; speeds in path units (mm or deg)
// per s, acceleration per s^2 (infinity where no axis has a limit).
struct PlannerMove {
  double length = 0.0;
  bool rotary_only = false;
  double requested_speed = 0.0;  // its feed: length / SegmentTime
  double axis_speed = 0.0;      // v_move: each axis within its velocity limit
  double triangle_speed = 0.0;  // sqrt(a_t L): reached and left within it
  double max_speed = 0.0;       // min(axis_speed, triangle_speed)
  double tangential_acceleration = 0.0;  // a_t
  double speed = 0.0;                    // min(requested_speed, max_speed)
};

// The move into pose i + 1, a feed move. Precondition as SegmentTime's.
PlannerMove PlanMove(const Machine& machine, const ToolPath& path,
                     const std::vector<JointVector>& joints, size_t i,
                     const PlannerOptions& options);

struct PlannerTime {
  double time_s = 0.0;       // the whole path
  double ramp_time_s = 0.0;  // of which the cost of the ramps
  int capped_moves = 0;      // feed moves slower than their feed (max_speed)
};

// Precondition: joints.size() == path.poses.size(), options valid.
PlannerTime PredictPlannerTime(const Machine& machine, const ToolPath& path,
                               const std::vector<JointVector>& joints,
                               const PlannerOptions& options);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PLANNER_TIME_H_
