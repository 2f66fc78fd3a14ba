// Everything the report says about one path: swept-cutter deviation from
// the surface (when there is one) and the motion on the machine.
#ifndef TPOPT_MODEL_PATH_METRICS_H_
#define TPOPT_MODEL_PATH_METRICS_H_

#include <optional>
#include <string>

#include "model/machine/axis_metrics.h"
#include "model/cutter/cutter.h"
#include "model/eval/deviation.h"
#include "model/machine/machine.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct PathMetrics {
  std::optional<DeviationReport> deviation;  // absent without a surface
  MotionReport motion;
  int poses = 0;
  // Feed moves marked as links (model/path/link_moves.h): kept as programmed,
  // and the motion's d2/ds2 peaks are not taken across them.
  int link_moves = 0;
  // Notes worth a user's attention (e.g. a pass near the A = 0 pole).
  std::string warning;
};

// Evaluates `path` on `machine` and, when `surface` is non-null, its
// deviation with `cutter`. Fails (naming the pose) when the path does not
// fit the machine's A travel or has a bad axis.
Status EvaluatePath(const ToolPath& path, const Machine& machine, const RuledSurface* surface,
                    const Cutter& cutter, const DeviationOptions& deviation_options,
                    const MotionOptions& motion_options, PathMetrics* metrics);

// Larger of the max overcut and max undercut, mm; 0 without a surface.
double WorstDeviationMm(const PathMetrics& metrics);

// True when `candidate` is worse than `reference` on deviation or on limit
// violations and better on neither: a smoother must not hand back such a
// path in place of its starting point.
bool IsWorseThan(const PathMetrics& candidate, const PathMetrics& reference);

}  // namespace tpopt

#endif  // TPOPT_MODEL_PATH_METRICS_H_
