// High-accuracy mode both ways round the A = 0 pole: each pole passage
// (solver/spline/pole_passage.h) of the initial guess is also tried the other way
// round, since the local solve keeps whichever side its guess takes.
#ifndef TPOPT_SOLVER_BOTH_WAYS_ROUND_POLES_H_
#define TPOPT_SOLVER_BOTH_WAYS_ROUND_POLES_H_

#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/smooth/ceres_smoother.h"

namespace tpopt {

// SmoothHighAccuracy from the initial guess and then, with a surface, from
// the guess with each passage of it (options.pole_passage_deg) taken the
// other way in turn, keeping each change that lowers the final cost. On a
// path longer than options.pole_window_path_poses a passage is tried in a
// window round it (seams held), both ways from the path solved so far, and
// the cheaper window spliced in; the whole problem's cost is then evaluated
// once more at the end. The report is the kept solve's, with the iterations
// and times of every solve added up and the passage counts filled in.
Status SmoothBothWaysRoundPoles(const SmoothingInputs& inputs,
                                const HighAccuracyOptions& options,
                                ToolPath* out, HighAccuracyReport* report);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_BOTH_WAYS_ROUND_POLES_H_
