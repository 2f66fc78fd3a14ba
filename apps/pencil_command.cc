// tpopt pencil: a pencil path on a bicubic B-spline surface from planar
// guide curves (seed 004), optionally written as the seed's cubic B-spline
// fit, with the chord error of straight moves against that of the fit.
#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/job_io.h"
#include "apps/options_from_flags.h"
#include "apps/report.h"
#include "model/io/pencil_job.h"
#include "solver/fit/pencil_fit.h"

namespace tpopt {
namespace {

Status UsageFromFlags(PencilOptions* pencil, bool* bspline, CurveOutputOptions* curve) {
  Status s = Require(FLAGS_surface, "surface");
  if (s.ok()) s = Require(FLAGS_curve, "curve");
  if (s.ok()) s = Require(FLAGS_out, "out");
  if (s.ok()) s = CheckGcodeFlags();
  if (s.ok()) s = PencilOptionsFromFlags(pencil);
  if (s.ok()) s = CurveOutputOptionsFromFlags(bspline, curve);
  return s;
}

nlohmann::json PencilReportJson(const Invocation& invocation, const PencilOptions& options,
                                const PencilFitResult& fit, size_t runs) {
  const SpanErrors& e = fit.errors;
  nlohmann::json j;
  j["command_line"] = invocation.command_line;
  j["runs"] = runs;
  j["cl_points"] = fit.cl_points;
  j["poses_out"] = fit.path.poses.size();
  j["curve_spans"] = fit.spans.size();
  j["step_mm"] = options.StepMm();
  j["max_chord_error_mm"] = e.max_chord_error_mm;
  j["max_fit_error_mm"] = e.max_fit_error_mm;
  j["chord_over_fit_error"] = e.max_chord_error_mm / std::max(e.max_fit_error_mm, 1e-300);
  j["max_join_angle_deg"] = e.max_join_angle_deg;
  j["folded_points"] = fit.folded_points;
  j["fit_windows"] = fit.windows;
  j["fit_time_per_window_us"] = 1e6 * fit.fit_seconds / std::max<size_t>(fit.windows, 1);
  return j;
}

}  // namespace

int RunPencil(const Invocation& invocation) {
  PencilOptions pencil;
  CurveOutputOptions curve_options;
  bool bspline = false;
  Status s = UsageFromFlags(&pencil, &bspline, &curve_options);
  if (!s.ok()) return ReportFailure("pencil", s);

  PencilJob job;
  Machine machine;
  std::optional<CadSurfaceInfo> cad;
  s = LoadBSplineSurface(FLAGS_surface, &job.surface, &cad);
  if (s.ok()) s = CompletePencilJob(FLAGS_curve, pencil.ball_radius_mm, &job);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &machine);
  if (!s.ok()) return ReportFailure("pencil", s);
  std::vector<PencilRun> runs;
  s = GeneratePencilRuns(job.geometry, job.guides, pencil, &runs);
  if (!s.ok()) return ReportFailure("pencil", s, FLAGS_curve + ": " + s.message());
  PencilFitResult fit;
  s = FitPencilRuns(job.geometry, job.guides, runs, pencil.ball_radius_mm, curve_options, bspline, &fit);
  if (!s.ok()) return ReportFailure("pencil", s, FLAGS_curve + ": " + s.message());

  fit.path.title = "tpopt pencil of " + FLAGS_curve + " on " + FLAGS_surface +
                   " (ball-end, tips = ball centre - radius along the axis)";
  fit.path.cutter = Cutter{pencil.ball_radius_mm, 4 * pencil.ball_radius_mm, 0.0};
  for (ToolPose& pose : fit.path.poses) {
    if (!pose.rapid) pose.feed_mm_per_min = pencil.feed_mm_per_min;
  }
  s = SaveToolPath(FLAGS_out, machine, fit.path, fit.spans);
  if (s.ok() && !FLAGS_report.empty()) {
    nlohmann::json report = PencilReportJson(invocation, pencil, fit, runs.size());
    if (cad) report["surface_cad"] = CadInfoJson(*cad);
    s = WriteReport(FLAGS_report, report);
  }
  if (!s.ok()) return ReportFailure("pencil", s);
  if (fit.folded_points > 0) {
    std::fprintf(stderr,
                 "warning: at %zu CL points the surface bends tighter than the %.3f mm ball along "
                 "the path: the ball gouges there (interference is not removed)\n",
                 fit.folded_points, pencil.ball_radius_mm);
  }
  if (!FLAGS_quiet) {
    std::printf("pencil: %zu runs, %zu CL points %.3f mm apart, %zu poses written\n",
                runs.size(), fit.cl_points, pencil.StepMm(), fit.path.poses.size());
    std::printf("  max chord error of straight moves %.3g mm, of the B-spline fit %.3g mm (%.0fx)\n",
                fit.errors.max_chord_error_mm, fit.errors.max_fit_error_mm,
                fit.errors.max_chord_error_mm / std::max(fit.errors.max_fit_error_mm, 1e-300));
    std::printf("  fit: %zu windows, %.3f us each; largest tangent step at a join %.3f deg\n",
                fit.windows, 1e6 * fit.fit_seconds / std::max<size_t>(fit.windows, 1),
                fit.errors.max_join_angle_deg);
  }
  return kExitSuccess;
}

}  // namespace tpopt
