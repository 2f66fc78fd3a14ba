// Per-axis motion of a path on the machine: peak velocity, acceleration and
// jerk of X, Y, Z (machine joints, mm) and A, C (rad), limit violations and
// the machining time, at the programmed feed.
//
// Timing model (TCP convention, as LinuxCNC's M428 / Heidenhain M128): the
// programmed feed is the speed of the tool tip in W, so a feed segment takes
// |d p_w_tip| / feed. A segment that moves only the rotaries takes
// max(|dA|, |dC|) in degrees / feed, as LinuxCNC reads F for rotary-only
// moves. A rapid takes the time of its slowest axis at that axis's velocity
// limit (or the tip at kDefaultRapidMmPerMin where no axis has a limit).
// Derivatives are finite differences on this time grid: the velocity of a
// segment is dJ / dt, the acceleration at a pose is the change of velocity
// over the mean of the two segment times, the jerk on a segment is the change
// of acceleration over its time. Rapids break the chain: only feed segments
// next to feed segments yield accelerations and jerks.
#ifndef TPOPT_MODEL_AXIS_METRICS_H_
#define TPOPT_MODEL_AXIS_METRICS_H_

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "model/machine/machine.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct AxisMotion {
  // Peaks of |derivative| in internal units: mm or rad per s, s^2, s^3.
  double peak_velocity = 0.0;
  double peak_acceleration = 0.0;
  double peak_jerk = 0.0;
  // Peak |d^2 J / ds^2| over the tip's arc length s, mm/mm^2 or rad/mm^2:
  // the feed-independent smoothness measure of the seed's spline method.
  // Taken within runs: not where a link (model/path/link_moves.h) meets a cut,
  // a corner the program makes and smoothing does not round.
  double peak_second_derivative_per_mm2 = 0.0;
  // Samples beyond the travel, velocity, acceleration or jerk limit.
  int limit_violations = 0;
};

struct MotionReport {
  std::array<AxisMotion, 5> axes;  // indexed by Axis
  int limit_violations = 0;        // sum over the axes
  double machining_time_s = 0.0;
  // The time on a blending planner (model/machine/planner_time.h): the feed moves'
  // ramps and the speed short moves cannot reach, which machining_time_s
  // leaves out.
  double planner_time_s = 0.0;
  double path_length_mm = 0.0;     // tip path in W over feed moves
  // Index of the pose with the worst limit violation, -1 if none.
  int worst_violation_pose = -1;
};

struct MotionOptions {
  // Feed used where a pose has none, mm/min. > 0.
  double default_feed_mm_per_min = 1000.0;
  bool IsValid(std::string* why) const;
};

constexpr double kDefaultRapidMmPerMin = 10000.0;

// The finite-difference derivatives behind the metrics, sample by sample.
// Segment i is the move into pose i + 1; acceleration i sits at pose i
// (between segments i - 1 and i); jerk i spans segment i - 1.
struct MotionSamples {
  std::vector<double> dt_s, ds_mm;       // per segment
  std::vector<bool> cutting;             // per segment: a feed move
  std::vector<JointVector> velocity;     // per segment
  std::vector<bool> has_acceleration;    // per pose
  std::vector<JointVector> acceleration; // per pose
  std::vector<bool> has_jerk;            // per pose
  std::vector<JointVector> jerk;         // per pose (over segment i - 1)
};

MotionSamples ComputeMotionSamples(const Machine& machine, const ToolPath& path,
                                   const std::vector<JointVector>& joints,
                                   double default_feed_mm_per_min);

// |d2q/ds2| at the middle of three poses from the joint's values q0, q1,
// q2 and the tips' travel ds0, ds1 (both > 0) between them: the change of
// slope over the mean step. A template so that the solver's cap on it
// (solver/smooth/cost/peak_second_cost.h) measures what the report does.
template <typename T>
T SecondDifferenceOverTravel(const T& q0, const T& q1, const T& q2, const T& ds0, const T& ds1) {
  using std::abs;
  return abs((q2 - q1) / ds1 - (q1 - q0) / ds0) / (T(0.5) * (ds0 + ds1));
}

// |d2 joint a / ds2| at pose i, units (mm or rad) per mm^2, s the tip's arc
// length: the divided difference whose peak the metrics report; 0 where it
// is not taken (i at either end, no acceleration sample there, a link on
// either side, or a move of zero length).
double SecondDerivativePerMm2(const ToolPath& path, const std::vector<JointVector>& joints,
                              const MotionSamples& m, size_t i, int a);

// Metrics for `path` whose joints are `joints` (from Machine::AssignJoints,
// one per pose). Precondition: joints.size() == path.poses.size().
MotionReport EvaluateMotion(const Machine& machine, const ToolPath& path,
                            const std::vector<JointVector>& joints,
                            const MotionOptions& options);

// Duration of the move into pose i + 1, seconds (timing model above).
double SegmentTime(const Machine& machine, const ToolPath& path,
                   const std::vector<JointVector>& joints, size_t i,
                   double default_feed_mm_per_min);

}  // namespace tpopt

#endif  // TPOPT_MODEL_AXIS_METRICS_H_
