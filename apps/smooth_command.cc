// tpopt smooth: the plain spline method or the high-accuracy mode, with the
// metrics of the input and the output side by side.
#include <cmath>
#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/inputs.h"
#include "apps/options_from_flags.h"
#include "apps/report.h"
#include "model/apt_io.h"
#include "solver/feed_scheduler.h"

namespace tpopt {
namespace {

int Fail(int code, const std::string& message) {
  std::fprintf(stderr, "tpopt smooth: %s\n", message.c_str());
  return code;
}

}  // namespace

int RunSmooth(const Invocation& invocation) {
  Status s = Require(FLAGS_in, "in");
  if (s.ok()) s = Require(FLAGS_out, "out");
  if (s.ok() && FLAGS_mode != "spline" && FLAGS_mode != "high_accuracy") {
    s = Status::Error("--mode=" + FLAGS_mode + " must be spline or high_accuracy");
  }
  DeviationOptions deviation_options;
  MotionOptions motion_options;
  SplineSmootherOptions spline_options;
  HighAccuracyOptions ha_options;
  if (s.ok()) s = MetricOptionsFromFlags(&deviation_options, &motion_options);
  if (s.ok()) s = SmootherOptionsFromFlags(&spline_options, &ha_options);
  if (s.ok() && FLAGS_mode == "high_accuracy" && FLAGS_surface.empty()) {
    s = Status::Error("--mode=high_accuracy needs --surface");
  }
  if (!s.ok()) return Fail(kExitUsage, s.message());

  Job job;
  PathMetrics in_metrics, guess_metrics, out_metrics;
  s = LoadJob(FLAGS_quiet, &job);
  auto evaluate = [&](const ToolPath& path, PathMetrics* metrics) {
    return EvaluatePath(path, job.machine, job.surface_or_null(), job.cutter, deviation_options,
                        motion_options, metrics);
  };
  if (s.ok()) {
    s = evaluate(job.path, &in_metrics);
    if (!s.ok()) s = Status::Error(FLAGS_in + ": " + s.message());
  }
  if (!s.ok()) return Fail(kExitBadInput, s.message());

  ToolPath spline_path, out_path;
  SplineSmootherReport spline_report;
  if (FLAGS_mode == "high_accuracy") spline_options.insert_transitions = false;
  s = SmoothWithSplines(job.path, job.machine, job.surface_or_null(), job.cutter, spline_options,
                        &spline_path, &spline_report);
  if (!s.ok()) return Fail(kExitBadInput, FLAGS_in + ": " + s.message());
  HighAccuracyReport ha_report;
  if (FLAGS_mode == "spline") {
    out_path = spline_path;
  } else {
    s = evaluate(spline_path, &guess_metrics);
    SmoothingInputs inputs{&job.path, &spline_path, &job.surface, &job.cutter, &job.machine};
    if (s.ok()) s = SmoothHighAccuracy(inputs, ha_options, &out_path, &ha_report);
    if (!s.ok()) return Fail(kExitBadInput, FLAGS_in + ": " + s.message());
    if (!ha_report.converged) {
      return Fail(kExitSolverFailure, "Ceres failed (" + ha_report.message +
                                          "); nothing written");
    }
  }
  PathMetrics unscheduled_metrics;
  s = evaluate(out_path, &unscheduled_metrics);
  if (!s.ok()) {
    return Fail(kExitSolverFailure, "the smoothed path does not fit the machine (" +
                                        s.message() + "); nothing written");
  }
  if (FLAGS_mode == "high_accuracy" && IsWorseThan(unscheduled_metrics, guess_metrics)) {
    return Fail(kExitSolverFailure,
                "the optimised path is worse than its spline starting point on deviation and "
                "limits; nothing written (try other weights)");
  }
  FeedScheduleReport feed_report;
  out_metrics = unscheduled_metrics;
  if (FLAGS_schedule_feed) {
    FeedScheduleOptions feed_options;
    feed_options.default_feed_mm_per_min = FLAGS_feed;
    std::vector<JointVector> joints;
    s = job.machine.AssignJoints(out_path, &joints);
    if (s.ok()) s = ScheduleFeed(job.machine, joints, feed_options, &out_path, &feed_report);
    if (s.ok()) s = evaluate(out_path, &out_metrics);
    if (!s.ok()) return Fail(kExitSolverFailure, "feed scheduling failed: " + s.message());
  }
  out_path.title = "tpopt smooth --mode=" + FLAGS_mode + " of " + FLAGS_in;
  s = WriteApt(FLAGS_out, out_path);
  if (!s.ok()) return Fail(kExitBadInput, s.message());

  if (!FLAGS_report.empty()) {
    nlohmann::json report = MetricsJson(out_metrics);
    report["tpopt_version"] = "0.1.0";
    report["command"] = invocation.command_line;
    report["mode"] = FLAGS_mode;
    report["input"] = MetricsJson(in_metrics);
    report["output"] = MetricsJson(out_metrics);
    report["poses_in"] = in_metrics.poses;
    report["poses_out"] = out_metrics.poses;
    report["spline"] = {{"zones", spline_report.zones},
                        {"poses_in_zones", spline_report.poses_in_zones},
                        {"poses_inserted", spline_report.poses_inserted},
                        {"max_angle_change_deg", spline_report.max_angle_change_deg}};
    report["output_at_input_feed"] = MetricsJson(unscheduled_metrics);
    report["feed_schedule"] = {{"enabled", FLAGS_schedule_feed},
                               {"passes", feed_report.passes},
                               {"moves_slowed", feed_report.moves_slowed},
                               {"min_feed_mm_per_min", feed_report.min_feed_mm_per_min},
                               {"violations_left", feed_report.violations_left}};
    report["iterations"] = ha_report.iterations;
    report["solve_time_s"] = ha_report.solve_time_s;
    if (FLAGS_mode == "high_accuracy") {
      report["initial_guess"] = MetricsJson(guess_metrics);
      report["ceres"] = {{"message", ha_report.message},
                         {"initial_cost", ha_report.initial_cost},
                         {"final_cost", ha_report.final_cost},
                         {"final_cost_by_family", ha_report.final_cost_by_family}};
    }
    s = WriteReport(FLAGS_report, report);
    if (!s.ok()) return Fail(kExitBadInput, s.message());
  }
  if (!FLAGS_quiet) {
    std::printf("%s%s", Summary("input ", in_metrics).c_str(),
                Summary("output", out_metrics).c_str());
    if (FLAGS_mode == "high_accuracy") {
      std::printf("  high_accuracy: %d iterations, %.3f s, cost %.4g -> %.4g\n",
                  ha_report.iterations, ha_report.solve_time_s, ha_report.initial_cost,
                  ha_report.final_cost);
    }
  }
  return kExitSuccess;
}

}  // namespace tpopt
