#include "solver/smooth/both_ways_round_poles.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "solver/smooth/coarse_to_fine.h"
#include "solver/spline/pole_passage.h"
#include "solver/smooth/windowed_solve.h"

namespace tpopt {
namespace {

// Poses each side of a passage that its re-solve frees too: the smoothness
// stencils carry a change of side along the path before it dies out. At
// least the passage's own length, and at least kMinMarginPoses.
constexpr size_t kMinMarginPoses = 100;

// The stretch of the path a passage's re-solve works on.
struct PassageWindow {
  size_t first = 0, last = 0;  // inclusive
  bool whole_path = false;
};

PassageWindow WindowAround(const PolePassage& passage, size_t poses,
                           const HighAccuracyOptions& options) {
  const size_t margin = std::max(kMinMarginPoses, passage.last - passage.first + 1);
  PassageWindow w;
  w.first = passage.first > margin ? passage.first - margin : 0;
  w.last = std::min(poses - 1, passage.last + margin);
  const size_t limit = static_cast<size_t>(options.pole_window_path_poses);
  w.whole_path = limit == 0 || poses <= limit || (w.first == 0 && w.last + 1 == poses);
  return w;
}

// The solved window, and the cost of the window's problem at its optimum.
struct WindowSolve {
  ToolPath poses;
  HighAccuracyReport report;
};

std::vector<size_t> WindowIndices(const PassageWindow& w) {
  std::vector<size_t> indices(w.last - w.first + 1);
  std::iota(indices.begin(), indices.end(), w.first);
  return indices;
}

// Solves poses [w.first, w.last] of the path from `guess` (the window's
// poses), its seams held at the guess where the window does not reach the
// path's ends.
Status SolveWindow(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                   const PassageWindow& w, const ToolPath& guess, WindowSolve* out) {
  const ToolPath window_input = SubPath(*inputs.input, WindowIndices(w));
  SmoothingInputs window = inputs;
  window.input = &window_input;
  window.initial_guess = &guess;
  window.held_first = w.first > 0 ? kHeldAtSeam : 0;
  window.held_last = w.last + 1 < inputs.input->poses.size() ? kHeldAtSeam : 0;
  return SmoothHighAccuracy(window, options, &out->poses, &out->report);
}

// The whole problem's cost, by family, at `path`: a solve of no iterations
// from it (windowed on a long path, as the solve itself was).
Status EvaluateFinalCost(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                         const ToolPath& path, HighAccuracyReport* report) {
  SmoothingInputs at_path = inputs;
  at_path.initial_guess = &path;
  HighAccuracyOptions evaluate_only = options;
  evaluate_only.max_iterations = 0;
  evaluate_only.coarse_poses = 0;  // coarse levels would move the path
  ToolPath unchanged;
  HighAccuracyReport evaluated;
  RETURN_IF_ERROR(SmoothHighAccuracy(at_path, evaluate_only, &unchanged, &evaluated));
  report->final_cost = evaluated.final_cost;
  report->final_cost_by_family = evaluated.final_cost_by_family;
  return Status::Ok();
}

// The whole path solved again from `other_guess` (the guess with a passage
// taken the other way); kept, with `solved`, `report` and `guess` updated,
// when its cost is lower. Iterations and times add up either way.
Status TryWholePath(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                    ToolPath other_guess, ToolPath* solved, HighAccuracyReport* report,
                    ToolPath* guess, bool* rerouted) {
  SmoothingInputs other_way = inputs;
  other_way.initial_guess = &other_guess;
  WindowSolve other;
  RETURN_IF_ERROR(SmoothHighAccuracy(other_way, options, &other.poses, &other.report));
  const int iterations = report->iterations + other.report.iterations;
  const double time_s = report->solve_time_s + other.report.solve_time_s;
  if (other.report.converged && other.report.final_cost < report->final_cost) {
    *solved = std::move(other.poses);
    *report = std::move(other.report);
    *guess = std::move(other_guess);
    *rerouted = true;
  }
  report->iterations = iterations;
  report->solve_time_s = time_s;
  return Status::Ok();
}

// Window `w` round `passage` solved again both ways from `solved` (the
// path so far), the passage's poses of the other way from `other_guess`;
// the cheaper window is spliced into `solved`. Costs of the same window
// problem compare; they do not add up to the whole path's (the weights are
// normalised by the problem's length), so `report`'s costs go stale.
Status TryWindow(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                 const PolePassage& passage, const PassageWindow& w, ToolPath other_guess,
                 ToolPath* solved, HighAccuracyReport* report, ToolPath* guess, bool* rerouted) {
  const ToolPath keep_guess = SubPath(*solved, WindowIndices(w));
  ToolPath turn_guess = keep_guess;
  for (size_t i = passage.first; i <= passage.last; ++i) {
    turn_guess.poses[i - w.first].p_w_tip = other_guess.poses[i].p_w_tip;
    turn_guess.poses[i - w.first].a_w = other_guess.poses[i].a_w;
  }
  WindowSolve keep, turn;
  RETURN_IF_ERROR(SolveWindow(inputs, options, w, keep_guess, &keep));
  RETURN_IF_ERROR(SolveWindow(inputs, options, w, turn_guess, &turn));
  report->iterations += keep.report.iterations + turn.report.iterations;
  report->solve_time_s += keep.report.solve_time_s + turn.report.solve_time_s;
  if (!keep.report.converged || !turn.report.converged) return Status::Ok();
  const bool turn_wins = turn.report.final_cost < keep.report.final_cost;
  const ToolPath& winner = turn_wins ? turn.poses : keep.poses;
  for (size_t i = 0; i < winner.poses.size(); ++i) {
    solved->poses[w.first + i].p_w_tip = winner.poses[i].p_w_tip;
    solved->poses[w.first + i].a_w = winner.poses[i].a_w;
  }
  if (turn_wins) {
    *guess = std::move(other_guess);
    *rerouted = true;
  }
  return Status::Ok();
}

// Tries `passage` the other way round on `solved` (the best path so far,
// whose report is `report`), from `guess` (the initial guess so far): the
// whole path again, or on a path longer than the passage's window only the
// window, so that a passage's cost stays bounded however long the path.
// Sets `rerouted` when the other way won (then `solved` and `guess` are
// updated) and `windowed` when only a window was solved (then `report`'s
// costs are stale).
Status TryTheOtherWay(const SmoothingInputs& inputs, const HighAccuracyOptions& options,
                      const PolePassage& passage, ToolPath* solved, HighAccuracyReport* report,
                      ToolPath* guess, bool* rerouted, bool* windowed) {
  *rerouted = false;
  ToolPath other_guess = RerouteAroundPole(*guess, passage, *inputs.cutter);
  const PassageWindow w = WindowAround(passage, solved->poses.size(), options);
  *windowed = !w.whole_path;
  if (w.whole_path) {
    return TryWholePath(inputs, options, std::move(other_guess), solved, report, guess, rerouted);
  }
  return TryWindow(inputs, options, passage, w, std::move(other_guess), solved, report, guess,
                   rerouted);
}

}  // namespace

Status SmoothBothWaysRoundPoles(const SmoothingInputs& inputs,
                                const HighAccuracyOptions& options,
                                ToolPath* out, HighAccuracyReport* report) {
  Status s = SmoothHighAccuracy(inputs, options, out, report);
  if (!s.ok() || !report->converged || inputs.surface == nullptr ||
      options.pole_passage_deg <= 0) {
    return s;
  }
  const ToolPath& start =
      inputs.initial_guess != nullptr ? *inputs.initial_guess : *inputs.input;
  const std::vector<PolePassage> passages =
      FindPolePassages(start, options.pole_passage_deg * M_PI / 180.0);
  ToolPath guess = start;
  int rerouted = 0, in_windows = 0;
  for (const PolePassage& passage : passages) {
    bool turned = false, windowed = false;
    RETURN_IF_ERROR(
        TryTheOtherWay(inputs, options, passage, out, report, &guess, &turned, &windowed));
    rerouted += turned;
    in_windows += windowed;
  }
  if (in_windows > 0) {
    RETURN_IF_ERROR(EvaluateFinalCost(inputs, options, *out, report));
  }
  report->pole_passages = static_cast<int>(passages.size());
  report->pole_passages_rerouted = rerouted;
  report->pole_passages_in_windows = in_windows;
  return Status::Ok();
}

}  // namespace tpopt
