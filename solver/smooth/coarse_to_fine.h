// Coarse-to-fine support for the high-accuracy solve on dense paths.
//
// A CAM path of 10,000 poses along one blade steps a few micrometres, far
// finer than the surface's own scale (the cutter radius, the guard
// distances of solver/smooth/cost/deviation_cost.h). Levenberg–Marquardt on such a
// path spends most of its iterations diffusing a correction along the
// stiff derivative stencils, one pose-width at a time. Solving first over
// a subset of "stations" (every k-th pose, and every pose that starts or
// ends a run), interpolating the optimised stations back onto every pose
// with cubic splines over the tip's arc length, and then refining the full
// problem from there gives the same optimum in a fraction of the time.
#ifndef TPOPT_SOLVER_COARSE_TO_FINE_H_
#define TPOPT_SOLVER_COARSE_TO_FINE_H_

#include <vector>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"
#include "solver/smooth/ceres_smoother.h"

namespace tpopt {

// Indices (increasing) of about `target` stations of `path`: the first and
// last pose, every rapid or link target and the pose before it (the ends of each
// run), and every stride-th pose in between, stride = ceil(n / target).
std::vector<size_t> CoarseStations(const ToolPath& path, size_t target);

// The poses `indices` of `path`, in order. With stations from
// CoarseStations every move keeps its rapid flag.
ToolPath SubPath(const ToolPath& path, const std::vector<size_t>& indices);

// `fine` with each pose between stations moved onto not-a-knot cubic splines
// (solver/spline/pose_spline.h) through the solved stations `coarse` (pose j of
// `coarse` belongs at fine pose stations[j]), run by run, over the fine
// path's tip arc length. Stations take their solved pose exactly.
Status InterpolateStations(const ToolPath& fine, const std::vector<size_t>& stations,
                           const ToolPath& coarse, const Machine& machine, ToolPath* out);

// Solves a path without consecutive repeated poses: directly when it has
// at most 2 x options.coarse_poses poses or no surface (surface-free, each
// pose has its own band around the original program, whose corners a
// subset of stations cannot represent), else over every 8th pose
// (recursively), interpolated back and refined for at most
// options.refine_iterations. Each level's solve is windowed when long
// (solver/smooth/windowed_solve.h). Poses the inputs hold (held_first, held_last)
// are stations of every level, held there too, and so keep the guess
// exactly.
Status SolveCoarseToFine(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                         ToolPath* out, HighAccuracyReport* report);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_COARSE_TO_FINE_H_
