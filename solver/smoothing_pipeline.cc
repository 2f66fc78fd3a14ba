#include "solver/smoothing_pipeline.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glog/logging.h>

#include "solver/pole_passage.h"

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
Status WithinTolerance(const DeviationReport& in, const DeviationReport& out,
                       double tolerance_mm) {
  CHECK_EQ(in.deviation_mm.size(), out.deviation_mm.size());
  size_t worst = out.deviation_mm.size();
  for (size_t k = 0; k < out.deviation_mm.size(); ++k) {
    const double d = std::abs(out.deviation_mm[k]);
    if (d <= tolerance_mm || d <= std::abs(in.deviation_mm[k])) continue;
    if (worst == out.deviation_mm.size() || d > std::abs(out.deviation_mm[worst])) worst = k;
  }
  if (worst == out.deviation_mm.size()) return Status::Ok();
  const size_t nv = out.v.size();
  std::ostringstream err;
  err << "the best path found is " << std::abs(out.deviation_mm[worst]) << " mm "
      << (out.deviation_mm[worst] < 0 ? "into" : "short of") << " the surface at (u "
      << out.u[worst / nv] << ", v " << out.v[worst % nv] << "), where the input was "
      << std::abs(in.deviation_mm[worst]) << " mm: beyond the tolerance of " << tolerance_mm
      << " mm";
  return Status::Error(err.str());
}

// How many times the solve's tolerance unit may be halved to bring the
// exact swept envelope within the stated tolerance.
constexpr int kToleranceTightenings = 2;

Status Fail(SmoothingFailure kind, const std::string& message, SmoothingFailure* failure) {
  *failure = kind;
  return Status::Error(message);
}

}  // namespace

Status RunSmoothing(const SmoothingJob& job, const SmoothingSettings& settings,
                    SmoothingResult* result, SmoothingFailure* failure) {
  CHECK(job.input && job.cutter && job.machine && result && failure);
  *failure = SmoothingFailure::kNone;
  const bool high_accuracy = settings.mode == SmoothingMode::kHighAccuracy;
  const auto& poses = job.input->poses;
  const bool cuts = std::any_of(poses.begin() + std::min<size_t>(1, poses.size()), poses.end(),
                                [](const ToolPose& p) { return !IsPositioningMove(p); });
  if (!cuts) {
    return Fail(SmoothingFailure::kBadInput,
                "the path has no cutting move to smooth (" + std::to_string(poses.size()) +
                    " poses)",
                failure);
  }
  auto stage = [&](const std::string& name) {
    if (settings.on_stage) settings.on_stage(name);
  };
  // With judge_on_input_range every path is judged on one grid: the
  // input's covered range (or the one asked for), never the range a
  // smoothed path happens to cover.
  DeviationOptions deviation = settings.deviation;
  auto evaluate = [&](const std::string& what, const ToolPath& path, PathMetrics* metrics) {
    stage("evaluating " + what);
    return EvaluatePath(path, *job.machine, job.surface, *job.cutter, deviation,
                        settings.motion, metrics);
  };
  Status s = evaluate("the input", *job.input, &result->input_metrics);
  // (The range itself, not the grid's ends: u_min + (u_max - u_min) i / n
  // can round past 1 at the last point.)
  if (s.ok() && job.surface != nullptr && settings.judge_on_input_range &&
      std::isnan(deviation.u_min)) {
    CoveredRangeU(*job.surface, *job.input, &deviation.u_min, &deviation.u_max);
  }
  if (s.ok()) s = WithinTravel(*job.machine, *job.input);
  if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);

  const SplineSmootherOptions spline_options =
      high_accuracy ? ForHighAccuracyGuess(settings.spline) : settings.spline;
  ToolPath spline_path;
  stage("spline smoothing");
  s = SmoothWithSplines(*job.input, *job.machine, job.surface, *job.cutter, spline_options,
                        &spline_path, &result->spline);
  if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);

  // Resamples result->output if asked, evaluates it and holds it to the
  // machine's travel.
  auto finish_output = [&]() {
    if (settings.resample_step_mm > 0) {
      stage("resampling");
      ResampleOptions resample;
      resample.step_mm = settings.resample_step_mm;
      Status r = ResamplePath(result->output, *job.machine, resample, &result->output);
      if (!r.ok()) return Fail(SmoothingFailure::kBadInput, "resampling: " + r.message(), failure);
    }
    Status r = evaluate("the output", result->output, &result->output_at_input_feed);
    if (r.ok()) r = WithinTravel(*job.machine, result->output);
    if (!r.ok()) {
      return Fail(SmoothingFailure::kSolver,
                  "the smoothed path does not fit the machine (" + r.message() + ")", failure);
    }
    return Status::Ok();
  };
  if (!high_accuracy) {
    result->output = std::move(spline_path);
    s = finish_output();
    if (!s.ok()) return s;
  } else {
    // Without a surface the band around the program is the only measure of
    // accuracy, and the input is the one start known to lie inside it.
    const ToolPath& guess = job.surface != nullptr ? spline_path : *job.input;
    s = evaluate("the initial guess", guess, &result->initial_guess_metrics);
    if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);
    const SmoothingInputs inputs{job.input, &guess, job.surface, job.cutter, job.machine};
    // The tolerance is also the unit the solve measures deviation in; where
    // the exact swept envelope still leaves it, the solve runs again with
    // that unit halved, which weighs the surface more against smoothness.
    HighAccuracyOptions options = settings.high_accuracy;
    options.interpolation = settings.deviation.interpolation;
    const bool held_to_tolerance = job.surface != nullptr && !settings.accept_over_tolerance;
    for (int round = 0;; ++round) {
      stage(round == 0 ? "high_accuracy solve"
                       : "high_accuracy solve, tolerance unit tightened to " +
                             std::to_string(options.tolerance_mm) + " mm");
      s = SmoothBothWaysRoundPoles(inputs, options, &result->output, &result->high_accuracy);
      if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);
      if (!result->high_accuracy.converged) {
        return Fail(SmoothingFailure::kSolver,
                    "Ceres failed (" + result->high_accuracy.message + ")", failure);
      }
      s = finish_output();
      if (!s.ok()) return s;
      if (IsWorseThan(result->output_at_input_feed, result->initial_guess_metrics)) {
        return Fail(SmoothingFailure::kSolver,
                    "the optimised path is worse than its spline starting point on deviation "
                    "and limits (try other weights)",
                    failure);
      }
      result->solve_tolerance_mm = options.tolerance_mm;
      if (!held_to_tolerance) break;
      s = WithinTolerance(*result->input_metrics.deviation,
                          *result->output_at_input_feed.deviation,
                          settings.high_accuracy.tolerance_mm);
      if (s.ok()) break;
      if (round == kToleranceTightenings) {
        return Fail(SmoothingFailure::kSolver,
                    s.message() + ", with the solve's unit tightened to " +
                        std::to_string(options.tolerance_mm) + " mm",
                    failure);
      }
      options.tolerance_mm *= 0.5;
    }
  }
  result->output_metrics = result->output_at_input_feed;
  if (!settings.schedule_feed) return Status::Ok();
  std::vector<JointVector> joints;
  stage("scheduling the feed");
  s = job.machine->AssignJoints(result->output, &joints);
  if (s.ok()) s = ScheduleFeed(*job.machine, joints, settings.feed, &result->output, &result->feed);
  if (s.ok()) s = evaluate("the output as written", result->output, &result->output_metrics);
  if (!s.ok()) return Fail(SmoothingFailure::kSolver, "feed scheduling: " + s.message(), failure);
  return Status::Ok();
}

}  // namespace tpopt
