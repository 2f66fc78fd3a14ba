#include "solver/smooth/coarse_to_fine.h"

#include <algorithm>
#include <chrono>

#include <glog/logging.h>

#include "solver/spline/pose_spline.h"
#include "solver/smooth/windowed_solve.h"

namespace tpopt {
namespace {

// The fine path's parameter: scaled to the path's own steps, so that the
// floor stays far below any real move at every size of part.
constexpr ArcLengthStepFloor kStationStepFloor = {1e-9, 1e-6};

// `stations` with every held pose added (the first `held_first` and the
// last `held_last` of n): a held pose must keep its guess at every level,
// and only a station is sure to.
std::vector<size_t> WithHeldPoses(std::vector<size_t> stations, size_t n, size_t held_first,
                                  size_t held_last) {
  for (size_t i = 0; i < std::min(held_first, n); ++i) stations.push_back(i);
  for (size_t i = n - std::min(held_last, n); i < n; ++i) stations.push_back(i);
  std::sort(stations.begin(), stations.end());
  stations.erase(std::unique(stations.begin(), stations.end()), stations.end());
  return stations;
}

}  // namespace

std::vector<size_t> CoarseStations(const ToolPath& path, size_t target) {
  const size_t n = path.poses.size();
  const size_t count = std::max<size_t>(target, 1);
  const size_t stride = std::max<size_t>(1, (n + count - 1) / count);
  std::vector<size_t> stations;
  for (size_t i = 0; i < n; ++i) {
    const bool run_end = i + 1 == n || IsPositioningMove(path.poses[i + 1]);
    const bool run_start = i == 0 || IsPositioningMove(path.poses[i]);
    if (run_start || i % stride == 0 || run_end) stations.push_back(i);
  }
  return stations;
}

ToolPath SubPath(const ToolPath& path, const std::vector<size_t>& indices) {
  // Not a copy of `path` with its poses cleared: windows take SubPaths of a
  // million-pose path dozens of times.
  ToolPath out = WithoutPoses(path);
  out.poses.reserve(indices.size());
  for (size_t i : indices) out.poses.push_back(path.poses[i]);
  return out;
}

Status InterpolateStations(const ToolPath& fine, const std::vector<size_t>& stations,
                           const ToolPath& coarse, const Machine& machine, ToolPath* out) {
  CHECK_EQ(stations.size(), coarse.poses.size());
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(coarse, &joints));
  const std::vector<double> s =
      TipArcLength(fine.poses.data(), fine.poses.size(), kStationStepFloor);
  ToolPath result = fine;
  // Each run [first, last] of the fine path starts and ends at a station.
  for (size_t j = 0; j < stations.size();) {
    size_t k = j + 1;
    while (k < stations.size() && !IsPositioningMove(fine.poses[stations[k]])) ++k;
    std::vector<size_t> members;
    std::vector<double> knots;
    for (size_t m = j; m < k; ++m) {
      members.push_back(m);
      knots.push_back(s[stations[m]]);
    }
    if (members.size() >= 2) {
      // Not-a-knot: a natural spline's straight ends put a false bend into
      // each run's first and last coarse step, whose third derivative the
      // finer level (at the rulings' departure weight) then took an extra
      // iteration to remove (BM_HighAccuracy/10000: 20 -> 19 iterations).
      PoseSpline spline;
      RETURN_IF_ERROR(
          PoseSpline::Fit(coarse, joints, members, knots, PoseSpline::Ends::kNotAKnot, &spline));
      for (size_t i = stations[j]; i <= stations[k - 1]; ++i) spline.Evaluate(s[i], &result.poses[i]);
    }
    for (size_t m = j; m < k; ++m) {
      result.poses[stations[m]].p_w_tip = coarse.poses[m].p_w_tip;
      result.poses[stations[m]].a_w = coarse.poses[m].a_w;
    }
    j = k;
  }
  *out = std::move(result);
  return Status::Ok();
}

Status SolveCoarseToFine(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                         ToolPath* out, HighAccuracyReport* report) {
  const size_t n = inputs.input->poses.size();
  if (inputs.surface == nullptr || options.coarse_poses == 0 ||
      n <= 2 * static_cast<size_t>(options.coarse_poses)) {
    return SolveInWindows(inputs, options, out, report);
  }
  const auto start = std::chrono::steady_clock::now();
  // Each level keeps one pose in kLevelRatio, down to coarse_poses.
  constexpr size_t kLevelRatio = 8;
  const size_t target = std::max<size_t>(options.coarse_poses, n / kLevelRatio);
  const std::vector<size_t> stations = WithHeldPoses(
      CoarseStations(*inputs.input, target), n, inputs.held_first, inputs.held_last);
  const ToolPath coarse_input = SubPath(*inputs.input, stations);
  const ToolPath coarse_guess =
      SubPath(inputs.initial_guess ? *inputs.initial_guess : *inputs.input, stations);
  SmoothingInputs coarse = inputs;
  coarse.input = &coarse_input;
  coarse.initial_guess = &coarse_guess;
  coarse.held_first = static_cast<size_t>(
      std::lower_bound(stations.begin(), stations.end(), inputs.held_first) - stations.begin());
  coarse.held_last = static_cast<size_t>(
      stations.end() -
      std::lower_bound(stations.begin(), stations.end(), n - std::min(inputs.held_last, n)));
  VLOG(1) << "high_accuracy: coarse solve over " << stations.size() << " of " << n << " poses";
  // The refinement finishes the job, so the coarse solve may stop once an
  // iteration changes its cost by less than 1e-4: the last dozen iterations
  // to 1e-6 moved the cost of the 10,000-pose impeller's coarsest level by
  // 0.7 % and cost a third of its time.
  HighAccuracyOptions coarse_options = options;
  coarse_options.function_tolerance = std::max(options.function_tolerance, 1e-4);
  ToolPath coarse_solved;
  HighAccuracyReport coarse_report;
  RETURN_IF_ERROR(SolveCoarseToFine(coarse, coarse_options, &coarse_solved, &coarse_report));
  ToolPath fine_guess;
  Status s =
      InterpolateStations(*inputs.input, stations, coarse_solved, *inputs.machine, &fine_guess);
  if (!s.ok()) {
    return Status::Error("the coarse level over " + std::to_string(stations.size()) + " of " +
                         std::to_string(n) + " poses (the value is the solver's): " +
                         s.message());
  }
  SmoothingInputs fine = inputs;
  fine.initial_guess = &fine_guess;
  // From the interpolated stations the deviation is already that of the
  // optimum (measured on the impeller: the same to 1e-6 mm); refinement
  // only polishes the smoothness, so it stops at a 0.1 % cost change.
  HighAccuracyOptions refine = options;
  refine.max_iterations = options.refine_iterations;
  refine.function_tolerance = std::max(options.function_tolerance, 1e-3);
  VLOG(1) << "high_accuracy: refining all " << n << " poses (at most " << refine.max_iterations
          << " iterations)";
  RETURN_IF_ERROR(SolveInWindows(fine, refine, out, report));
  report->iterations += coarse_report.iterations;
  report->converged = report->converged && coarse_report.converged;
  report->solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tpopt
