#include "solver/smoothing_pipeline.h"

#include <algorithm>

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
                                [](const ToolPose& p) { return !p.rapid; });
  if (!cuts) {
    return Fail(SmoothingFailure::kBadInput,
                "the path has no cutting move to smooth (" + std::to_string(poses.size()) +
                    " poses)",
                failure);
  }
  auto stage = [&](const std::string& name) {
    if (settings.on_stage) settings.on_stage(name);
  };
  auto evaluate = [&](const std::string& what, const ToolPath& path, PathMetrics* metrics) {
    stage("evaluating " + what);
    return EvaluatePath(path, *job.machine, job.surface, *job.cutter, settings.deviation,
                        settings.motion, metrics);
  };
  Status s = evaluate("the input", *job.input, &result->input_metrics);
  if (s.ok()) s = WithinTravel(*job.machine, *job.input);
  if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);

  SplineSmootherOptions spline_options = settings.spline;
  // The Ceres problem keeps the input's poses one for one.
  if (high_accuracy) spline_options.insert_transitions = false;
  ToolPath spline_path;
  stage("spline smoothing");
  s = SmoothWithSplines(*job.input, *job.machine, job.surface, *job.cutter, spline_options,
                        &spline_path, &result->spline);
  if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);
  if (!high_accuracy) {
    result->output = std::move(spline_path);
  } else {
    // Without a surface the band around the program is the only measure of
    // accuracy, and the input is the one start known to lie inside it.
    const ToolPath& guess = job.surface != nullptr ? spline_path : *job.input;
    s = evaluate("the initial guess", guess, &result->initial_guess_metrics);
    const SmoothingInputs inputs{job.input, &guess, job.surface, job.cutter, job.machine};
    if (s.ok()) stage("high_accuracy solve");
    if (s.ok()) s = SmoothBothWaysRoundPoles(inputs, settings.high_accuracy, &result->output,
                                             &result->high_accuracy);
    if (!s.ok()) return Fail(SmoothingFailure::kBadInput, s.message(), failure);
    if (!result->high_accuracy.converged) {
      return Fail(SmoothingFailure::kSolver, "Ceres failed (" + result->high_accuracy.message + ")",
                  failure);
    }
  }
  if (settings.resample_step_mm > 0) {
    stage("resampling");
    ResampleOptions resample;
    resample.step_mm = settings.resample_step_mm;
    s = ResamplePath(result->output, *job.machine, resample, &result->output);
    if (!s.ok()) return Fail(SmoothingFailure::kBadInput, "resampling: " + s.message(), failure);
  }
  s = evaluate("the output", result->output, &result->output_at_input_feed);
  if (s.ok()) s = WithinTravel(*job.machine, result->output);
  if (!s.ok()) {
    return Fail(SmoothingFailure::kSolver,
                "the smoothed path does not fit the machine (" + s.message() + ")", failure);
  }
  if (high_accuracy && IsWorseThan(result->output_at_input_feed, result->initial_guess_metrics)) {
    return Fail(SmoothingFailure::kSolver,
                "the optimised path is worse than its spline starting point on deviation and "
                "limits (try other weights)",
                failure);
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
