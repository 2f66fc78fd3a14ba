#include "solver/smoothing_pipeline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>

#include <glog/logging.h>

#include "model/axis_metrics.h"
#include "solver/pole_passage.h"
#include "solver/surface_placement.h"

namespace tpopt {
namespace {

// A smoother that moves a pose outside the travel writes a program the
// machine stops on, so both ends of the run are held to it.
Status WithinTravel(const Machine& machine, const ToolPath& path) {
  std::vector<JointVector> joints;
  Status s = machine.AssignJoints(path, &joints);
  if (s.ok()) s = machine.CheckTravel(path, joints);
  return s;
}

// The stated tolerance is a promise about what the smoother does to the
// path, judged on the exact swept envelope (not the solver's sample points):
// no point of the surface may end up farther from the cutter than the
// tolerance unless the input was farther still there (at poses the smoother
// must hold, such as the targets of rapids, the input's error stands).
// Returns the grid points (indices into out.deviation_mm) that break it;
// `slack_mm` is how far past the input's error counts as the input's (the
// same moves evaluated again can differ in the last bits).
std::vector<size_t> BeyondTolerance(const DeviationReport& in, const DeviationReport& out,
                                    double tolerance_mm, double slack_mm = 0.0) {
  CHECK_EQ(in.deviation_mm.size(), out.deviation_mm.size());
  std::vector<size_t> beyond;
  for (size_t k = 0; k < out.deviation_mm.size(); ++k) {
    const double d = std::abs(out.deviation_mm[k]);
    if (d > tolerance_mm && d > std::abs(in.deviation_mm[k]) + slack_mm) beyond.push_back(k);
  }
  return beyond;
}

// Why the result is refused: how many points are beyond, and the worst.
std::string BeyondToleranceMessage(const DeviationReport& in, const DeviationReport& out,
                                   const std::vector<size_t>& beyond, double tolerance_mm) {
  CHECK(!beyond.empty());
  const size_t worst = *std::max_element(beyond.begin(), beyond.end(), [&](size_t a, size_t b) {
    return std::abs(out.deviation_mm[a]) < std::abs(out.deviation_mm[b]);
  });
  const size_t nv = out.v.size();
  std::ostringstream err;
  err << "the best path found is " << std::abs(out.deviation_mm[worst]) << " mm "
      << (out.deviation_mm[worst] < 0 ? "into" : "short of") << " the surface at (u "
      << out.u[worst / nv] << ", v " << out.v[worst % nv] << "), where the input was "
      << std::abs(in.deviation_mm[worst]) << " mm: beyond the tolerance of " << tolerance_mm
      << " mm at " << beyond.size() << " of " << out.deviation_mm.size() << " grid points";
  return err.str();
}

// The tolerance is a constraint, not a weight: the points a solve leaves
// beyond it join an active set that the next solve holds with a penalty of
// its own (ceres_smoother.h, TolerancePoint), multiplied by kPenaltyGrowth
// each round a point is still beyond, so that the rest of the surface keeps
// the weights the smoothing was tuned with. After kToleranceRounds rounds
// what is still beyond is taken to be infeasible and refused.
constexpr int kToleranceRounds = 4;
constexpr double kFirstPenalty = 10.0;
constexpr double kPenaltyGrowth = 10.0;

// Adds the grid points `beyond` and their four neighbours on the grid to
// `active` (a point held alone hands its excess to the next grid point
// along u), or raises the penalty of those in it already.
void GrowActiveSet(const DeviationReport& out, const std::vector<size_t>& beyond,
                   std::vector<TolerancePoint>* active) {
  const int nu = static_cast<int>(out.u.size()), nv = static_cast<int>(out.v.size());
  std::vector<TolerancePoint> grown = *active;
  for (size_t k : beyond) {
    const int iu = static_cast<int>(k) / nv, iv = static_cast<int>(k) % nv;
    const int offsets[5][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};
    for (const auto& d : offsets) {
      const int ju = iu + d[0], jv = iv + d[1];
      if (ju < 0 || ju >= nu || jv < 0 || jv >= nv) continue;
      const double u = out.u[ju], v = out.v[jv];
      auto same = [&](const TolerancePoint& p) { return p.u == u && p.v == v; };
      auto it = std::find_if(grown.begin(), grown.end(), same);
      if (it == grown.end()) {
        grown.push_back({u, v, kFirstPenalty});
      } else if (std::find_if(active->begin(), active->end(), same) != active->end() &&
                 d[0] == 0 && d[1] == 0) {
        // Held in the last solve and still beyond: hold it harder.
        it->weight *= kPenaltyGrowth;
      }
    }
  }
  *active = std::move(grown);
}

// The peak |d2A/ds2| and |d2C/ds2| of each cutting run of `path` (runs as
// RunEnd splits them), over the samples at the run's poses.
Status RunPeaks(const ToolPath& path, const Machine& machine, double default_feed_mm_per_min,
                std::vector<std::array<double, 2>>* peaks) {
  std::vector<JointVector> joints;
  RETURN_IF_ERROR(machine.AssignJoints(path, &joints));
  const MotionSamples m = ComputeMotionSamples(machine, path, joints, default_feed_mm_per_min);
  peaks->clear();
  for (size_t first = 0; first < path.poses.size();) {
    const size_t end = RunEnd(path, first);
    std::array<double, 2> peak = {0.0, 0.0};
    for (size_t i = first; i < end; ++i) {
      peak[0] = std::max(peak[0], SecondDerivativePerMm2(path, joints, m, i, kA));
      peak[1] = std::max(peak[1], SecondDerivativePerMm2(path, joints, m, i, kC));
    }
    peaks->push_back(peak);
    first = end;
  }
  return Status::Ok();
}

// Where each cutting run of `path` starts, with path.poses.size() last.
std::vector<size_t> RunStarts(const ToolPath& path) {
  std::vector<size_t> first;
  for (size_t i = 0; i < path.poses.size(); i = RunEnd(path, i)) first.push_back(i);
  first.push_back(path.poses.size());
  return first;
}

// `output` with the runs r where back[r] replaced by the same runs of
// `input` (the two paths' runs pair up, RunStarts of each).
ToolPath ComposeRuns(const ToolPath& input, const ToolPath& output, const std::vector<bool>& back) {
  const std::vector<size_t> in_first = RunStarts(input), out_first = RunStarts(output);
  CHECK_EQ(in_first.size(), back.size() + 1);
  CHECK_EQ(out_first.size(), back.size() + 1);
  ToolPath composed = WithoutPoses(output);
  for (size_t r = 0; r < back.size(); ++r) {
    const ToolPath& from = back[r] ? input : output;
    const std::vector<size_t>& first = back[r] ? in_first : out_first;
    composed.poses.insert(composed.poses.end(), from.poses.begin() + first[r],
                          from.poses.begin() + first[r + 1]);
  }
  return composed;
}

// Puts back as programmed every run of `output` whose peak d2A/ds2 or
// d2C/ds2 is higher than that of the same run of `input`, so that the
// program as a whole is no worse on either; `back` (one flag a run) says
// which, and may come in with runs already put back. A run's first sample
// also sees the last pose of the run before, which a method may move: a run
// put back that is still worse puts its predecessor back too, until none is
// (at worst the whole input). False, with nothing changed, when the two
// paths' runs do not pair up (which no method makes) or joints cannot be
// assigned.
bool KeepRunsNoWorse(const ToolPath& input, const Machine& machine, double default_feed_mm_per_min,
                     ToolPath* output, std::vector<bool>* back) {
  std::vector<std::array<double, 2>> before, after;
  if (!RunPeaks(input, machine, default_feed_mm_per_min, &before).ok() ||
      !RunPeaks(*output, machine, default_feed_mm_per_min, &after).ok() ||
      before.size() != after.size()) {
    return false;
  }
  const size_t runs = before.size();
  if (back->size() != runs) back->assign(runs, false);
  ToolPath composed = ComposeRuns(input, *output, *back);
  if (!RunPeaks(composed, machine, default_feed_mm_per_min, &after).ok()) return false;
  // Round-off of the written 6 decimals is no worsening.
  constexpr double kSlack = 1e-9;
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t r = 0; r < runs; ++r) {
      if (after[r][0] <= before[r][0] + kSlack && after[r][1] <= before[r][1] + kSlack) continue;
      if (!(*back)[r]) {
        (*back)[r] = changed = true;
      } else if (r > 0 && !(*back)[r - 1]) {
        (*back)[r - 1] = changed = true;
      }
    }
    if (!changed) break;
    composed = ComposeRuns(input, *output, *back);
    if (!RunPeaks(composed, machine, default_feed_mm_per_min, &after).ok()) return false;
  }
  *output = std::move(composed);
  return true;
}

using Evaluator = std::function<Status(const std::string& what, const ToolPath& path,
                                        PathMetrics* metrics)>;

// High accuracy, a step after the solve and its tolerance check: the runs
// the solve made worse on peak d2A/ds2 or d2C/ds2 go back as programmed
// (KeepRunsNoWorse), so the mode never returns a program worse on either.
// A put-back run is the input's own poses, so where it alone cuts, the
// deviation is the input's and the tolerance (which spares what the input
// left) holds there. Where a put-back run and a moved neighbour both reach a
// point, the mix can leave it farther than either did: if the composed
// program breaks the tolerance (when `tolerance_mm` > 0), the neighbours of
// the put-back runs go back too, until it holds (at worst the whole input,
// which the tolerance never refuses). On success result->output and
// output_at_input_feed are the composed program's, and runs_kept_as_input
// counts the runs put back.
// A put-back run's moves evaluated in the composed path give the input's
// deviation to round-off (seen: 1e-17 mm above it); a nanometre is far
// below any tolerance.
constexpr double kSameMovesSlackMm = 1e-6;

Status KeepSolvedRunsNoWorse(const SmoothingJob& job, double default_feed_mm_per_min,
                             double tolerance_mm, const Evaluator& evaluate,
                             SmoothingResult* result) {
  std::vector<bool> back;
  for (;;) {
    ToolPath composed = result->output;
    if (!KeepRunsNoWorse(*job.input, *job.machine, default_feed_mm_per_min, &composed, &back)) {
      return Status::Ok();
    }
    const int kept = static_cast<int>(std::count(back.begin(), back.end(), true));
    if (kept == 0) return Status::Ok();
    PathMetrics metrics;
    RETURN_IF_ERROR(evaluate("the output with " + std::to_string(kept) + " runs kept as programmed",
                             composed, &metrics));
    RETURN_IF_ERROR(WithinTravel(*job.machine, composed));
    if (tolerance_mm <= 0.0 || kept == static_cast<int>(back.size()) ||
        BeyondTolerance(*result->input_metrics.deviation, *metrics.deviation, tolerance_mm,
                        kSameMovesSlackMm)
            .empty()) {
      result->output = std::move(composed);
      result->output_at_input_feed = std::move(metrics);
      result->runs_kept_as_input = kept;
      return Status::Ok();
    }
    std::vector<bool> grown = back;
    for (size_t r = 0; r < back.size(); ++r) {
      if (!back[r]) continue;
      if (r > 0) grown[r - 1] = true;
      if (r + 1 < back.size()) grown[r + 1] = true;
    }
    if (grown == back) grown.assign(back.size(), true);
    back = std::move(grown);
  }
}

// What the stages of one RunSmoothing share: the job and its settings, the
// result being filled, and the grid every path is judged on.
struct SmoothingRun {
  const SmoothingJob& job;
  const SmoothingSettings& settings;
  SmoothingResult* result;
  // With judge_on_input_range every path is judged on one grid: the
  // input's covered range (or the one asked for), never the range a
  // smoothed path happens to cover.
  DeviationOptions deviation;

  void Stage(const std::string& name) const {
    if (settings.on_stage) settings.on_stage(name);
  }

  Status Evaluate(const std::string& what, const ToolPath& path, PathMetrics* metrics) const {
    Stage("evaluating " + what);
    return EvaluatePath(path, *job.machine, job.surface, *job.cutter, deviation, settings.motion,
                        metrics);
  }

  // Resamples result->output if asked, evaluates it and holds it to the
  // machine's travel.
  Status FinishOutput() const {
    if (settings.resample_step_mm > 0) {
      Stage("resampling");
      ResampleOptions resample;
      resample.step_mm = settings.resample_step_mm;
      Status r = ResamplePath(result->output, *job.machine, resample, &result->output);
      if (!r.ok()) return Status::Error("resampling: " + r.message());
    }
    Status r = Evaluate("the output", result->output, &result->output_at_input_feed);
    if (r.ok()) r = WithinTravel(*job.machine, result->output);
    if (!r.ok()) {
      return Status::SolverFailure("the smoothed path does not fit the machine (" + r.message() +
                                   ")");
    }
    return Status::Ok();
  }
};

// The input's metrics (fixing the judged range) and its travel.
Status JudgeInput(SmoothingRun* run) {
  const SmoothingJob& job = run->job;
  SmoothingResult* result = run->result;
  Status s = run->Evaluate("the input", *job.input, &result->input_metrics);
  // (The range itself, not the grid's ends: u_min + (u_max - u_min) i / n
  // can round past 1 at the last point.)
  if (s.ok() && job.surface != nullptr && run->settings.judge_on_input_range &&
      std::isnan(run->deviation.u_min)) {
    CoveredRangeU(*job.surface, *job.input, &run->deviation.u_min, &run->deviation.u_max);
  }
  if (s.ok()) s = WithinTravel(*job.machine, *job.input);
  if (!s.ok()) return Status::Error(s.message());
  return Status::Ok();
}

// Without a surface the band around the program is the only measure of
// accuracy, and the input is the one start known to lie inside it. With
// one, the start is the spline path or the poses placed on the surface
// at their own contacts (solver/surface_placement.h), whichever the
// judge finds nearer the surface: a noisy CAM path's spline stays as far
// off as the input (tenths of a millimetre), and the solve from there
// ends in a local minimum. Sets result->initial_guess_metrics and
// start_placed_on_surface; `placed` holds the placed poses.
Status ChooseStart(const SmoothingRun& run, const ToolPath& spline_path, ToolPath* placed) {
  const SmoothingJob& job = run.job;
  SmoothingResult* result = run.result;
  bool start_placed = false;
  if (job.surface != nullptr) {
    Status s = run.Evaluate("the spline start", spline_path, &result->initial_guess_metrics);
    if (!s.ok()) return Status::SolverFailure("spline start: " + s.message());
    run.Stage("placing the poses on the surface");
    PathMetrics placed_metrics;
    s = PlaceOnSurface(*job.input, *job.surface, *job.cutter, placed);
    if (s.ok()) s = run.Evaluate("the placed start", *placed, &placed_metrics);
    if (!s.ok()) return Status::SolverFailure("placement: " + s.message());
    if (WorstDeviationMm(placed_metrics) < WorstDeviationMm(result->initial_guess_metrics)) {
      start_placed = true;
      result->initial_guess_metrics = std::move(placed_metrics);
    }
  } else {
    Status s = run.Evaluate("the initial guess", *job.input, &result->initial_guess_metrics);
    if (!s.ok()) return Status::Error(s.message());
  }
  result->start_placed_on_surface = start_placed;
  return Status::Ok();
}

// The high-accuracy solve from `guess`, solved again with the points it
// leaves beyond the tolerance held (when held_to_tolerance), and refused
// if still beyond after kToleranceRounds or worse than its start.
Status SolveWithinTolerance(const SmoothingRun& run, const ToolPath& guess,
                            const HighAccuracyOptions& options, bool held_to_tolerance) {
  const SmoothingJob& job = run.job;
  SmoothingResult* result = run.result;
  std::vector<TolerancePoint> active;
  SmoothingInputs inputs{job.input, &guess, job.surface, job.cutter, job.machine};
  inputs.tolerance_points = &active;
  for (int round = 0;; ++round) {
    run.Stage(round == 0 ? "high_accuracy solve"
                         : "high_accuracy solve, " + std::to_string(active.size()) +
                               " points held to the tolerance");
    // The input passed its checks above, so whatever the solve reports
    // is the solver's failure, not the input's.
    Status s = SmoothBothWaysRoundPoles(inputs, options, &result->output, &result->high_accuracy);
    if (!s.ok()) {
      return Status::SolverFailure("the high_accuracy solve failed: " + s.message());
    }
    if (!result->high_accuracy.converged) {
      return Status::SolverFailure(
          "the high_accuracy solve failed: Ceres found no usable solution (" +
          result->high_accuracy.message + ")");
    }
    RETURN_IF_ERROR(run.FinishOutput());
    result->solve_tolerance_mm = options.tolerance_mm;
    result->tolerance_rounds = round;
    result->tolerance_points = static_cast<int>(active.size());
    if (held_to_tolerance) {
      const DeviationReport& in = *result->input_metrics.deviation;
      const DeviationReport& out = *result->output_at_input_feed.deviation;
      const std::vector<size_t> beyond = BeyondTolerance(in, out, options.tolerance_mm);
      if (!beyond.empty() && round == kToleranceRounds) {
        double heaviest = 0.0;
        for (const TolerancePoint& p : active) heaviest = std::max(heaviest, p.weight);
        std::ostringstream why;
        why << BeyondToleranceMessage(in, out, beyond, options.tolerance_mm) << ", after "
            << round << " rounds holding " << active.size()
            << " points to the tolerance with penalties up to " << heaviest
            << " times the surface's weight";
        return Status::SolverFailure(why.str());
      }
      if (!beyond.empty()) {
        GrowActiveSet(out, beyond, &active);
        continue;
      }
    }
    // The path to be returned. Held to the tolerance it leaves no grid
    // point beyond both the tolerance and the input, a pointwise promise
    // that the start, itself beyond the tolerance where a noisy input
    // happened to be within it, need not keep: judged against the
    // start's max |dev| alone, a solve that met it was refused. So there
    // it is worse only when it breaks more axis limits than the start and
    // the input and is not nearer the surface than the start.
    const PathMetrics& out_metrics = result->output_at_input_feed;
    const PathMetrics& start_metrics = result->initial_guess_metrics;
    const bool worse =
        IsWorseThan(out_metrics, start_metrics) &&
        (!held_to_tolerance ||
         out_metrics.motion.limit_violations >
             std::max(start_metrics.motion.limit_violations,
                      result->input_metrics.motion.limit_violations));
    if (worse) {
      return Status::SolverFailure(
          held_to_tolerance
              ? "the optimised path breaks more axis limits than its starting point and the "
                "input, and is no nearer the surface than its start (try other weights)"
              : "the optimised path is worse than its starting point on deviation and limits "
                "(try other weights)");
    }
    return Status::Ok();
  }
}

// High-accuracy mode after the spline method: the start, the solve held to
// the tolerance, then the runs it made worse put back.
Status SolveHighAccuracy(const SmoothingRun& run, const ToolPath& spline_path) {
  const SmoothingJob& job = run.job;
  const SmoothingSettings& settings = run.settings;
  ToolPath placed;
  RETURN_IF_ERROR(ChooseStart(run, spline_path, &placed));
  const bool start_placed = run.result->start_placed_on_surface;
  const ToolPath& guess =
      job.surface == nullptr ? *job.input : start_placed ? placed : spline_path;
  HighAccuracyOptions options = settings.high_accuracy;
  options.interpolation = settings.deviation.interpolation;
  const bool held_to_tolerance = job.surface != nullptr && !settings.accept_over_tolerance;
  RETURN_IF_ERROR(SolveWithinTolerance(run, guess, options, held_to_tolerance));
  Status s;
  if (settings.keep_runs_no_worse) {
    const Evaluator evaluate = [&run](const std::string& what, const ToolPath& path,
                                      PathMetrics* metrics) {
      return run.Evaluate(what, path, metrics);
    };
    s = KeepSolvedRunsNoWorse(job, settings.feed.default_feed_mm_per_min,
                              held_to_tolerance ? options.tolerance_mm : 0.0, evaluate,
                              run.result);
  }
  if (!s.ok()) {
    return Status::SolverFailure(
        "the smoothed path with runs kept as programmed does not fit the machine (" +
        s.message() + ")");
  }
  return Status::Ok();
}

// The feed scheduled on the output (raised feeds held to the input's own
// peaks), and the output's metrics as written.
Status ScheduleOutputFeed(const SmoothingRun& run) {
  const SmoothingJob& job = run.job;
  SmoothingResult* result = run.result;
  std::vector<JointVector> joints;
  run.Stage("scheduling the feed");
  Status s = job.machine->AssignJoints(result->output, &joints);
  FeedScheduleOptions feed = run.settings.feed;
  for (int a = 0; a < 5; ++a) {  // what raised feeds may ask of each axis at most
    feed.input_peak_acceleration[a] = result->input_metrics.motion.axes[a].peak_acceleration;
    feed.input_peak_jerk[a] = result->input_metrics.motion.axes[a].peak_jerk;
  }
  if (s.ok()) s = ScheduleFeed(*job.machine, joints, feed, &result->output, &result->feed);
  if (s.ok()) s = run.Evaluate("the output as written", result->output, &result->output_metrics);
  if (!s.ok()) return Status::SolverFailure("feed scheduling: " + s.message());
  return Status::Ok();
}

}  // namespace

Status RunSmoothing(const SmoothingJob& job, const SmoothingSettings& settings,
                    SmoothingResult* result) {
  CHECK(job.input && job.cutter && job.machine && result);
  const bool high_accuracy = settings.mode == SmoothingMode::kHighAccuracy;
  const auto& poses = job.input->poses;
  const auto second = poses.begin() + std::min<size_t>(1, poses.size());
  const bool feeds = std::any_of(second, poses.end(), [](const ToolPose& p) { return !p.rapid; });
  const bool cuts =
      std::any_of(second, poses.end(), [](const ToolPose& p) { return !IsPositioningMove(p); });
  if (!feeds) {
    return Status::Error("the path has no cutting move to smooth (" + std::to_string(poses.size()) +
                         " poses)");
  }
  SmoothingRun run{job, settings, result, settings.deviation};
  RETURN_IF_ERROR(JudgeInput(&run));
  if (!cuts) {
    // Every feed move is one to keep as programmed (held, such as a
    // program of pure rotary moves, or a link): the program goes out as it
    // came, with nothing smoothed.
    result->output = *job.input;
    result->output_at_input_feed = result->output_metrics = result->input_metrics;
    return Status::Ok();
  }

  const SplineSmootherOptions spline_options =
      high_accuracy ? ForHighAccuracyGuess(settings.spline) : settings.spline;
  ToolPath spline_path;
  run.Stage("spline smoothing");
  Status s = SmoothWithSplines(*job.input, *job.machine, job.surface, *job.cutter, spline_options,
                               &spline_path, &result->spline);
  // The input was read and fits the machine: a method that fails on it fails
  // as a solver.
  if (!s.ok()) return Status::SolverFailure("spline smoothing: " + s.message());

  if (!high_accuracy) {
    result->output = std::move(spline_path);
    std::vector<bool> back;
    if (settings.keep_runs_no_worse &&
        KeepRunsNoWorse(*job.input, *job.machine, settings.feed.default_feed_mm_per_min,
                        &result->output, &back)) {
      result->runs_kept_as_input = static_cast<int>(std::count(back.begin(), back.end(), true));
    }
    RETURN_IF_ERROR(run.FinishOutput());
  } else {
    RETURN_IF_ERROR(SolveHighAccuracy(run, spline_path));
  }
  result->output_metrics = result->output_at_input_feed;
  if (!settings.schedule_feed) return Status::Ok();
  return ScheduleOutputFeed(run);
}

}  // namespace tpopt
