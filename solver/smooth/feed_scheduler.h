// Feed scheduling: lowers the programmed feed move by move until every axis
// keeps its velocity, acceleration and jerk limits (as model/machine/axis_metrics.h
// measures them), so that the program the controller reads is feasible as
// written. Smoothing removes the needless peaks; what the geometry itself
// demands (a tight turn of the blade, a pass near the A = 0 pole) can only
// be met by slowing down there, which is what a controller's look-ahead
// would otherwise do unannounced.
//
// Method: feeds start at the programmed values; each pass scales the feed of
// the moves around every violation by margin * (limit / value)^(1/k) (k = 1,
// 2, 3: velocity, acceleration and jerk grow as feed^k), then bounds the
// ratio of neighbouring feeds by (1 + max_feed_step) both ways so that the
// change of feed does not itself accelerate the axes; passes repeat until no
// violation is left. In the default mode (kLower) feeds are never raised
// above the programmed ones.
//
// kRaise turns smoothness into time: every feed move starts at its ceiling,
// min(max_feed_mm_per_min, max_feed_factor * programmed feed), and the same
// passes lower it where a limit needs; so each move ends at about the fastest
// feed (within the margin) that keeps every axis's limits, or at its ceiling.
// The neighbour bound holds from the first pass, so the raised program has
// no feed jump above (1 + max_feed_step) between feed moves, even where the
// program had one (an inverse-time program, whose every move takes the same
// time, has one at every change of move length): a planner that keeps the
// programmed feed otherwise accelerates at its limit at each such jump.
// Raising feeds must not ask more of any joint than the program did: with
// keep_input_peaks the acceleration and jerk ceilings of each axis are
// min(the machine's limit, the input's own peak over its cuts), which the
// caller passes in input_peak_*. A move's ceiling is also the speed a
// blending planner can reach and leave again within it (the triangle speed
// of model/machine/planner_time.h), so no F asks for a speed the controller would
// not give.
//
// kKeepRunTime keeps the program's time and smooths its speed: each cutting
// run (feed moves between rapids, links and held moves) keeps its total time
// at the programmed feeds, but the time is spread over its moves in
// proportion to a smooth tip speed, the program's own mean speed over
// keep_run_time_window_mm of path around each move (time-weighted: path
// length over time), scaled so the run takes the time it took. In an
// inverse-time program, whose every move takes one of a few fixed times
// whatever its length, this removes the speed jump at every change of move
// length while each run, and so the program, takes as long as before. The
// passes of kLower then lower it where a limit needs.
#ifndef TPOPT_SOLVER_FEED_SCHEDULER_H_
#define TPOPT_SOLVER_FEED_SCHEDULER_H_

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

enum class FeedMode { kLower, kRaise, kKeepRunTime };

struct FeedScheduleOptions {
  FeedMode mode = FeedMode::kLower;
  // kRaise only: the ceilings of a feed move, mm/min (> 0; infinity: none)
  // and as a factor of its programmed feed (>= 1).
  double max_feed_mm_per_min = std::numeric_limits<double>::infinity();
  double max_feed_factor = 2.0;
  // kRaise: keep each axis's acceleration and jerk within the input's own
  // peaks, input_peak_acceleration / input_peak_jerk (per Axis, mm or rad
  // per s^2, s^3; infinity: no ceiling), which the caller fills from the
  // input program's metrics (solver/smooth/smoothing_pipeline does).
  bool keep_input_peaks = true;
  std::array<double, 5> input_peak_acceleration = UnlimitedAxes();
  std::array<double, 5> input_peak_jerk = UnlimitedAxes();
  // kKeepRunTime: length of path, mm, over which the program's tip speed is
  // averaged. > 0; infinity: one speed over each run.
  double keep_run_time_window_mm = 10.0;
  // Each correction aims this fraction below the limit. (0, 1).
  double margin = 0.97;
  // Largest relative feed change between neighbouring moves. > 0.
  double max_feed_step = 0.1;
  // Feed where a pose has none, mm/min. > 0.
  double default_feed_mm_per_min = 1000.0;
  int max_passes = 200;

  bool IsValid(std::string* why) const;

  static std::array<double, 5> UnlimitedAxes() {
    std::array<double, 5> a;
    a.fill(std::numeric_limits<double>::infinity());
    return a;
  }
};

struct FeedScheduleReport {
  int passes = 0;
  int moves_slowed = 0;  // below the programmed feed
  int moves_raised = 0;  // above it (kRaise, kKeepRunTime)
  int runs_retimed = 0;  // kKeepRunTime: cutting runs whose time was spread anew
  double min_feed_mm_per_min = 0.0;
  double max_feed_mm_per_min = 0.0;
  int violations_left = 0;  // 0 unless max_passes ran out
};

// Rewrites the feeds of `path`'s feed moves. `joints` from
// Machine::AssignJoints on `path`.
Status ScheduleFeed(const Machine& machine, const std::vector<JointVector>& joints,
                    const FeedScheduleOptions& options, ToolPath* path,
                    FeedScheduleReport* report);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_FEED_SCHEDULER_H_
