// tpopt smooth: the plain spline method or the high-accuracy mode, with the
// metrics of the input and the output side by side.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/controller_run.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/job_io.h"
#include "apps/options_from_flags.h"
#include "apps/picture_outputs.h"
#include "apps/progress_display.h"
#include "apps/report.h"
#include "model/base/invalid_field.h"
#include "model/base/units.h"
#include "model/io/apt_io.h"
#include "solver/smooth/smoothing_pipeline.h"

namespace tpopt {
namespace {

// Shows the pipeline's stages and Ceres' iterations on `progress`; null
// detaches them.
void ReportProgressTo(ProgressDisplay* progress, SmoothingSettings* settings) {
  if (progress == nullptr) {
    settings->on_stage = nullptr;
    settings->high_accuracy.on_iteration = nullptr;
    return;
  }
  settings->on_stage = [progress](const std::string& stage) { progress->SetStage(stage); };
  settings->high_accuracy.on_iteration = [progress](int iteration, double cost) {
    char detail[64];
    std::snprintf(detail, sizeof(detail), "iteration %d, cost %.4e", iteration, cost);
    progress->SetDetail(detail);
  };
}

// The output path, then the report, HTML and VTK files the flags ask for.
// Writes the path as `written` (the result, or points on its fitted
// B-spline `spans`), the report and the pictures of the result.
Status WriteOutputs(const Invocation& invocation, const Job& job, const SmoothingResult& result,
                    Interpolation interpolation, const ToolPath& written,
                    const std::vector<AptCurveSpan>& spans) {
  Status s = SaveToolPath(FLAGS_out, job.machine, written, spans, &job.path);
  if (s.ok() && !FLAGS_report.empty()) {
    nlohmann::json report = SmoothReportJson(invocation, FLAGS_mode, result);
    if (job.surface_cad) report["surface_cad"] = CadInfoJson(*job.surface_cad);
    if (job.controller) {
      report["controller"] =
          ControllerRunJson(*job.controller, result.output_metrics.motion.planner_time_s);
    }
    report["interpolation"] = InterpolationName(interpolation);
    report["cutter"] = {{"radius_mm", job.cutter.radius_mm},
                        {"flute_length_mm", job.cutter.flute_length_mm},
                        {"per_tool", job.cutter_per_tool}};
    s = WriteReport(FLAGS_report, report);
  }
  if (s.ok()) {
    s = WritePictures("tpopt smooth --mode=" + FLAGS_mode + " of " + FLAGS_in,
                      invocation.command_line,
                      {{"before", &job.path, &result.input_metrics},
                       {"after", &result.output, &result.output_metrics}},
                      job);
  }
  return s;
}

// One run put back as programmed: its lines, why, and the figures judged.
std::string DescribeKeptRun(const KeptRun& k) {
  char line[512];
  int n = std::snprintf(line, sizeof line, "lines %d-%d: ", k.first_line, k.last_line);
  const size_t room = sizeof line - n;
  if (k.reason == "d2") {
    std::snprintf(line + n, room, "peak d2%s/ds2 %.4g -> %.4g deg/mm^2 (input -> smoothed)",
                  k.axis.c_str(), k.input_peak * kRadToDeg, k.smoothed_peak * kRadToDeg);
  } else if (k.reason == "limits") {
    std::snprintf(line + n, room, "axis-limit violations %d -> %d (input -> smoothed)",
                  k.input_violations, k.smoothed_violations);
  } else if (k.reason == "tolerance") {
    std::snprintf(line + n, room,
                  "tolerance: %.5f mm at (u %.4f, v %.4f), %.5f mm beyond it (input %.5f mm)",
                  k.worst_mm, k.u, k.v, k.beyond_mm, k.input_mm);
  } else if (k.reason == "solver") {
    std::snprintf(line + n, room, "the solve failed: %s", k.solver_message.c_str());
  } else if (k.neighbour_line > 0) {
    std::snprintf(line + n, room, "with its neighbour from line %d", k.neighbour_line);
  } else {
    std::snprintf(line + n, room, "with its neighbours");
  }
  return line;
}

std::string DescribeRougherRun(const RougherRun& k) {
  char line[256];
  std::snprintf(line, sizeof line,
                "lines %d-%d: peak d2%s/ds2 %.4g -> %.4g deg/mm^2 (input -> smoothed); "
                "programmed %.4g mm off the surface",
                k.first_line, k.last_line, k.axis.c_str(), k.input_peak * kRadToDeg,
                k.smoothed_peak * kRadToDeg, k.input_worst_mm);
  return line;
}

// One line a run, the first kMaxRunLines of them (the report lists all).
void PrintRunLines(const std::vector<std::string>& lines) {
  constexpr size_t kMaxRunLines = 20;
  for (size_t i = 0; i < lines.size() && i < kMaxRunLines; ++i) {
    std::printf("    %s\n", lines[i].c_str());
  }
  if (lines.size() > kMaxRunLines) {
    std::printf("    ... and %zu more\n", lines.size() - kMaxRunLines);
  }
}

void PrintSummary(const SmoothingSettings& settings, const SmoothingResult& result) {
  std::printf("%s%s", Summary("input ", result.input_metrics).c_str(),
              Summary("output", result.output_metrics).c_str());
  if (settings.mode == SmoothingMode::kHighAccuracy) {
    const HighAccuracyReport& ha = result.high_accuracy;
    std::printf("  high_accuracy: %d iterations, %.3f s, cost %.4g -> %.4g\n", ha.iterations,
                ha.solve_time_s, ha.initial_cost, ha.final_cost);
    if (result.tolerance_rounds > 0) {
      std::printf("  %d more solves held %d grid points to the tolerance of %.4g mm\n",
                  result.tolerance_rounds, result.tolerance_points,
                  settings.high_accuracy.tolerance_mm);
    }
    if (result.input_joint_bow_mm > 0) {
      std::printf(
          "  solved with each cutting move split in %d: under joint interpolation the "
          "program's moves bow up to %.4g mm off their line\n",
          result.moves_per_move, result.input_joint_bow_mm);
    } else if (result.moves_per_move > 1) {
      std::printf(
          "  solved again with each cutting move split in %d: the program's own moves "
          "put %d runs back as programmed\n",
          result.moves_per_move, result.runs_kept_at_program_moves);
    }
    const FlankRoughness& flank = result.flank_roughness;
    if (flank.measured && settings.stiffer_above_flank_d2 > 0 &&
        flank.Ratio() > settings.stiffer_above_flank_d2) {
      std::printf(
          "  rougher than the surface's own flank path: peak d2%s/ds2 %.4g deg/mm^2 at line %d, "
          "%.3g x the flank path's %.4g (above --stiffer_above_flank_d2 %.3g)\n",
          flank.axis.c_str(), flank.smoothed_peak * kRadToDeg, flank.line, flank.Ratio(),
          flank.flank_peak * kRadToDeg, settings.stiffer_above_flank_d2);
    }
    if (ha.pole_passages > 0) {
      std::printf("  pole passages: %d solved both ways round A = 0 (%d in a window round them), "
                  "%d kept the other way\n",
                  ha.pole_passages, ha.pole_passages_in_windows, ha.pole_passages_rerouted);
    }
  }
  if (result.spline.pole_crossings > 0) {
    std::printf("  spline: %d pole passages routed through A = 0 (A changes sign, C held)\n",
                result.spline.pole_crossings);
  }
  if (result.runs_kept_as_input > 0) {
    std::printf("  %d cutting runs kept as programmed: smoothing made their peak d2A/ds2 or "
                "d2C/ds2 higher (in high accuracy also: broke more axis limits, left "
                "points beyond the tolerance, or every solve failed)\n",
                result.runs_kept_as_input);
    std::vector<std::string> lines;
    for (const KeptRun& k : result.runs_kept) lines.push_back(DescribeKeptRun(k));
    PrintRunLines(lines);
  }
  if (!result.runs_rougher.empty()) {
    std::printf(
        "  %d cutting runs rougher than programmed: each programmed run leaves the "
        "surface beyond the tolerance, and the smoothed one stays within "
        "--stiffer_above_flank_d2 times the surface's own flank path's peak d2\n",
        static_cast<int>(result.runs_rougher.size()));
    std::vector<std::string> lines;
    for (const RougherRun& k : result.runs_rougher) lines.push_back(DescribeRougherRun(k));
    PrintRunLines(lines);
  }
  if (result.feed.moves_slowed > 0) {
    std::printf("  feed scheduled down on %d moves (lowest %.0f mm/min) to keep every limit\n",
                result.feed.moves_slowed, result.feed.min_feed_mm_per_min);
  }
  if (result.feed.moves_raised > 0) {
    std::printf("  feed raised on %d moves (highest %.0f mm/min) within every limit\n",
                result.feed.moves_raised, result.feed.max_feed_mm_per_min);
  }
}

// --mode=none: the input as the output, evaluated once, so that a program
// goes out through the same reader and writer as a smoothed one.
Status PassThrough(const Job& job, const SmoothingSettings& settings, SmoothingResult* result) {
  RETURN_IF_ERROR(EvaluatePath(job.path, job.machine, job.surface_or_null(), job.cutter,
                               settings.deviation, settings.motion, &result->input_metrics));
  result->output = job.path;
  result->output_at_input_feed = result->input_metrics;
  result->output_metrics = result->input_metrics;
  return Status::Ok();
}

// What the flags ask of one `tpopt smooth` run.
struct SmoothRequest {
  SmoothingSettings settings;
  LinkMoveOptions links;
  bool bspline_output = false;
  CurveOutputOptions curve_options;
};

// Every flag of the run, checked in order; a failure is a usage error.
Status RequestFromFlags(SmoothRequest* request) {
  SmoothingSettings& settings = request->settings;
  RETURN_IF_ERROR(Require(FLAGS_in, "in"));
  RETURN_IF_ERROR(Require(FLAGS_out, "out"));
  RETURN_IF_ERROR(CheckGcodeFlags());
  RETURN_IF_ERROR(CheckPartSetupFlag());
  RETURN_IF_ERROR(CheckPictureFlags());
  if (FLAGS_mode != "spline" && FLAGS_mode != "high_accuracy" && FLAGS_mode != "none") {
    return Status::Usage("--mode=" + FLAGS_mode + " must be spline, high_accuracy or none");
  }
  settings.mode = FLAGS_mode == "spline" ? SmoothingMode::kSpline : SmoothingMode::kHighAccuracy;
  settings.schedule_feed = FLAGS_schedule_feed;
  settings.accept_over_tolerance = FLAGS_accept_over_tolerance;
  settings.keep_runs_no_worse = FLAGS_keep_runs_no_worse;
  settings.stiffer_above_flank_d2 = FLAGS_stiffer_above_flank_d2;
  settings.stiffer_solves = FLAGS_stiffer_solves;
  settings.peak_d2_cap_over_flank = FLAGS_peak_d2_cap_over_flank;
  settings.peak_deviation_rounds = FLAGS_peak_deviation_rounds;
  settings.judge_on_input_range = FLAGS_judge_on_input_range;
  settings.even_stations = FLAGS_even_stations;
  settings.split_moves_for_tolerance = FLAGS_split_moves_for_tolerance;
  settings.resample_step_mm = FLAGS_resample_step_mm;
  RETURN_IF_ERROR(FeedScheduleOptionsFromFlags(&settings.feed));
  RETURN_IF_ERROR(MetricOptionsFromFlags(&settings.deviation, &settings.motion));
  RETURN_IF_ERROR(
      InterpolationFromFlags(FLAGS_out, FLAGS_gcode_style, &settings.deviation.interpolation));
  RETURN_IF_ERROR(LinkMoveOptionsFromFlags(&request->links));
  RETURN_IF_ERROR(
      SmootherOptionsFromFlags(FLAGS_surface.empty(), &settings.spline, &settings.high_accuracy));
  if (!(FLAGS_resample_step_mm >= 0)) {
    return Status::Usage("--resample_step_mm=" + std::to_string(FLAGS_resample_step_mm) +
                         " must be >= 0");
  }
  if (!(FLAGS_stiffer_above_flank_d2 >= 0) || !std::isfinite(FLAGS_stiffer_above_flank_d2)) {
    return Status::Usage(InvalidField("--stiffer_above_flank_d2", FLAGS_stiffer_above_flank_d2,
                                      "finite and >= 0"));
  }
  if (!(FLAGS_peak_d2_cap_over_flank >= 0) || !std::isfinite(FLAGS_peak_d2_cap_over_flank)) {
    return Status::Usage(
        InvalidField("--peak_d2_cap_over_flank", FLAGS_peak_d2_cap_over_flank, "finite and >= 0"));
  }
  if (FLAGS_stiffer_solves < 0 || FLAGS_stiffer_solves > SmoothingSettings::kMaxStifferSolves) {
    return Status::Usage(
        InvalidField("--stiffer_solves", FLAGS_stiffer_solves,
                     "between 0 and " + std::to_string(SmoothingSettings::kMaxStifferSolves)));
  }
  if (FLAGS_split_moves_for_tolerance < 1 ||
      FLAGS_split_moves_for_tolerance > SmoothingSettings::kMaxSplitMoves) {
    return Status::Usage(
        InvalidField("--split_moves_for_tolerance", FLAGS_split_moves_for_tolerance,
                     "between 1 and " + std::to_string(SmoothingSettings::kMaxSplitMoves)));
  }
  if (FLAGS_peak_deviation_rounds < 0) {
    return Status::Usage(InvalidField("--peak_deviation_rounds", FLAGS_peak_deviation_rounds,
                                      ">= 0"));
  }
  return CurveOutputOptionsFromFlags(&request->bspline_output, &request->curve_options);
}

// The job smoothed (or passed through, --mode=none) into `result`, with the
// progress display while it runs.
Status SmoothJob(const Job& job, SmoothingSettings* settings, SmoothingResult* result) {
  Status s;
  if (FLAGS_mode == "none") {
    s = PassThrough(job, *settings, result);
  } else {
    // Gone before the summary is printed, so its line never splits it.
    ProgressDisplay progress(stderr, "tpopt smooth", !FLAGS_quiet, FLAGS_progress_after_s);
    ReportProgressTo(&progress, settings);
    s = RunSmoothing({&job.path, job.surface_or_null(), &job.cutter, &job.machine}, *settings,
                     result);
  }
  ReportProgressTo(nullptr, settings);
  return s;
}

}  // namespace

int RunSmooth(const Invocation& invocation) {
  SmoothRequest request;
  Status s = RequestFromFlags(&request);
  if (!s.ok()) return ReportFailure("smooth", s);
  SmoothingSettings& settings = request.settings;

  s = CheckOutputFolders({FLAGS_out, FLAGS_report, FLAGS_html, FLAGS_vtk});
  Job job;
  if (s.ok()) s = LoadJob(FLAGS_quiet, request.links, &job);
  if (!s.ok()) return ReportFailure("smooth", s);
  settings.deviation.cutter_per_tool = job.cutter_per_tool;
  SmoothingResult result;
  s = SmoothJob(job, &settings, &result);
  if (!s.ok()) {
    return ReportFailure("smooth", s,
                         s.code() == StatusCode::kSolver ? s.message() + "; nothing written"
                                                         : FLAGS_in + ": " + s.message());
  }
  result.output.title = "tpopt smooth --mode=" + FLAGS_mode + " of " + FLAGS_in;
  ToolPath written = result.output;
  std::vector<AptCurveSpan> spans;
  if (request.bspline_output) {
    s = FitToolPathCurves(result.output, request.curve_options, &written, &spans);
    if (!s.ok()) {
      return ReportFailure("smooth", s, FLAGS_out + ": the B-spline fit failed: " + s.message());
    }
  }
  s = WriteOutputs(invocation, job, result, settings.deviation.interpolation, written, spans);
  if (!s.ok()) return ReportFailure("smooth", s);
  if (!FLAGS_quiet) {
    PrintSummary(settings, result);
    if (request.bspline_output) {
      std::printf("  B-spline output: %zu cubic spans, %zu poses written (points on the spans)\n",
                  spans.size(), written.poses.size());
    }
  }
  return kExitSuccess;
}

}  // namespace tpopt
