// Feed scheduling: lowers the programmed feed move by move until every axis
// keeps its velocity, acceleration and jerk limits (as model/axis_metrics.h
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
#ifndef TPOPT_SOLVER_FEED_SCHEDULER_H_
#define TPOPT_SOLVER_FEED_SCHEDULER_H_

#include <limits>
#include <string>
#include <vector>

#include "model/machine.h"
#include "model/status.h"
#include "model/tool_path.h"

namespace tpopt {

enum class FeedMode { kLower, kRaise };

struct FeedScheduleOptions {
  FeedMode mode = FeedMode::kLower;
  // kRaise only: the ceilings of a feed move, mm/min (> 0; infinity: none)
  // and as a factor of its programmed feed (>= 1).
  double max_feed_mm_per_min = std::numeric_limits<double>::infinity();
  double max_feed_factor = 2.0;
  // Each correction aims this fraction below the limit. (0, 1).
  double margin = 0.97;
  // Largest relative feed change between neighbouring moves. > 0.
  double max_feed_step = 0.1;
  // Feed where a pose has none, mm/min. > 0.
  double default_feed_mm_per_min = 1000.0;
  int max_passes = 200;

  bool IsValid(std::string* why) const;
};

struct FeedScheduleReport {
  int passes = 0;
  int moves_slowed = 0;  // below the programmed feed
  int moves_raised = 0;  // above it (kRaise)
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
