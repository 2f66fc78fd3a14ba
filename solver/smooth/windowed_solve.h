// The high-accuracy problem of a long path, solved in overlapping windows
// so that memory stays bounded whatever the pose count.
//
// Windows of options.window_poses poses advance along the path; each
// window starts window_poses / 10 poses before the previous one ended.
// The first three poses of a window (the widest derivative stencil) are
// held at what the previous window made of them, so every stencil across
// a seam is optimised in the window that follows it and the path stays
// continuous there. A window's far end is free, like the end of a path:
// holding it at the initial guess would pull the window's last stretch
// towards the guess (README, "Figures behind the defaults"). A window keeps its result from its first free pose on;
// the next window then overwrites the overlap. Paths no longer than one
// window are solved whole. Poses the inputs hold at the path's ends stay
// held in the first and the last window.
#ifndef TPOPT_SOLVER_WINDOWED_SOLVE_H_
#define TPOPT_SOLVER_WINDOWED_SOLVE_H_

#include <cstddef>

#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/smooth/ceres_smoother.h"

namespace tpopt {

// Poses held at a seam: the widest stencil (third differences) spans four
// poses, so three held poses give every stencil at the seam a free pose.
constexpr size_t kHeldAtSeam = 3;

// As SolveWholeProblem (same preconditions), windowed when the path has
// more than options.window_poses poses. The report sums the windows'
// iterations and costs; converged only when every window converged.
Status SolveInWindows(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                      ToolPath* out, HighAccuracyReport* report);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_WINDOWED_SOLVE_H_
