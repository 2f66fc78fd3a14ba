#include "solver/smooth/windowed_solve.h"

#include <algorithm>
#include <chrono>
#include <numeric>

#include <glog/logging.h>

#include "solver/smooth/coarse_to_fine.h"

namespace tpopt {
namespace {

void Accumulate(const HighAccuracyReport& window, HighAccuracyReport* total) {
  total->converged = total->converged && window.converged;
  total->message = window.message;
  total->iterations += window.iterations;
  total->initial_cost += window.initial_cost;
  total->final_cost += window.final_cost;
  total->poses_clamped += window.poses_clamped;
  for (const auto& [family, cost] : window.final_cost_by_family) {
    total->final_cost_by_family[family] += cost;
  }
}

}  // namespace

Status SolveInWindows(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                      ToolPath* out, HighAccuracyReport* report) {
  const size_t n = inputs.input->poses.size();
  const size_t width = static_cast<size_t>(options.window_poses);
  if (width == 0 || n <= width) return SolveWholeProblem(inputs, options, out, report);
  const auto start = std::chrono::steady_clock::now();
  const size_t overlap = std::max<size_t>(width / 10, 4 * kHeldAtSeam);
  const size_t windows = 1 + (n - width + (width - overlap) - 1) / (width - overlap);
  // The path as solved so far: the guess ahead of the current window.
  ToolPath current = inputs.initial_guess ? *inputs.initial_guess : *inputs.input;
  *report = HighAccuracyReport();
  report->converged = true;
  size_t first = 0;
  for (size_t k = 0; first < n; ++k) {
    const size_t end = std::min(n, first + width);
    std::vector<size_t> indices(end - first);
    std::iota(indices.begin(), indices.end(), first);
    const ToolPath window_input = SubPath(*inputs.input, indices);
    const ToolPath window_guess = SubPath(current, indices);
    SmoothingInputs window = inputs;
    window.input = &window_input;
    window.initial_guess = &window_guess;
    window.held_first = first > 0 ? kHeldAtSeam : inputs.held_first;
    window.held_last = end == n ? inputs.held_last : 0;
    ToolPath solved;
    HighAccuracyReport window_report;
    RETURN_IF_ERROR(SolveWholeProblem(window, options, &solved, &window_report));
    for (size_t i = window.held_first; i < indices.size(); ++i) {
      current.poses[first + i].p_w_tip = solved.poses[i].p_w_tip;
      current.poses[first + i].a_w = solved.poses[i].a_w;
    }
    Accumulate(window_report, report);
    VLOG(1) << "high_accuracy: window " << k + 1 << "/" << windows << ", poses " << first << "-"
            << end - 1 << ", " << window_report.iterations << " iterations";
    if (end == n) break;
    first = end - overlap;
  }
  *out = *inputs.input;
  for (size_t i = 0; i < n; ++i) {
    out->poses[i].p_w_tip = current.poses[i].p_w_tip;
    out->poses[i].a_w = current.poses[i].a_w;
  }
  report->solve_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return Status::Ok();
}

}  // namespace tpopt
