// tpopt stripwidth: a strip-width machining pass with a torus cutter over a
// bicubic surface, positioned by Sturz's method, the multi-point method or
// mid-point error control (solver/strip/tool_posture.h), written as a CL path
// with a report of strip widths, tool-centre fluctuation and A/C motion.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/job_io.h"
#include "apps/options_from_flags.h"
#include "apps/report.h"
#include "model/geometry/freeform_surface.h"
#include "model/eval/path_metrics.h"
#include "model/base/units.h"
#include "solver/strip/strip_path.h"
#include "solver/strip/strip_path_metrics.h"

namespace tpopt {
namespace {

Status OptionsFromFlags(TorusCutter* cutter, StripPathOptions* options) {
  RETURN_IF_ERROR(Require(FLAGS_surface, "surface"));
  RETURN_IF_ERROR(Require(FLAGS_out, "out"));
  RETURN_IF_ERROR(Require(FLAGS_cutter, "cutter"));
  RETURN_IF_ERROR(CheckGcodeFlags());
  return StripPathOptionsFromFlags(cutter, options);
}

nlohmann::json PointsJson(const std::vector<StripPoint>& points) {
  nlohmann::json list = nlohmann::json::array();
  for (const StripPoint& p : points) {
    list.push_back({{"u", p.u},
                    {"v", p.v},
                    {"width_mm", p.strip.width()},
                    {"s_minus_mm", p.strip.s_minus},
                    {"s_plus_mm", p.strip.s_plus},
                    {"truncated", p.strip.truncated},
                    {"min_deviation_mm", p.strip.min_deviation},
                    {"max_deviation_in_strip_mm", p.strip.max_deviation_in_strip},
                    {"lead_deg", p.posture.lead_rad / kDegToRad},
                    {"tilt_deg", p.posture.tilt_rad / kDegToRad},
                    {"contact_offset_mm", p.posture.contact_s_mm}});
  }
  return list;
}

nlohmann::json StripMetricsJson(const StripPathMetrics& m) {
  return {{"mean_width_mm", m.mean_width_mm},
          {"min_width_mm", m.min_width_mm},
          {"max_width_mm", m.max_width_mm},
          {"truncated_strips", m.truncated_strips},
          {"worst_deviation_mm", m.worst_deviation_mm},
          {"max_deviation_in_strip_mm", m.max_deviation_in_strip_mm},
          {"max_strip_mid_offset_mm", m.max_strip_mid_offset_mm},
          {"centre_fluctuation_max_mm", m.centre_fluctuation_max_mm},
          {"centre_fluctuation_rms_mm", m.centre_fluctuation_rms_mm},
          {"cc_second_difference_max_mm", m.cc_second_difference_max_mm}};
}

// The pass planned on the surface, as CC points and as the CL path written,
// with the machine's motion along it and the time the planning took.
struct StripRun {
  FreeformSurface surface;
  Machine machine;
  std::optional<CadSurfaceInfo> cad;
  std::vector<StripPoint> points;
  ToolPath path;
  PathMetrics motion;
  double solve_s = 0.0;
};

// Loads the surface and the machine, plans the pass and measures its
// motion; `run->path` is made even on failure (as the report's title needs
// the surface's name).
Status PlanStripRun(const TorusCutter& cutter, const StripPathOptions& options,
                    const DeviationOptions& deviation_options, const MotionOptions& motion_options,
                    StripRun* run) {
  const auto start = std::chrono::steady_clock::now();
  Status s = LoadFreeformSurface(FLAGS_surface, &run->surface, &run->cad);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &run->machine);
  if (s.ok()) {
    s = PlanStripPath(run->surface, cutter, options, &run->points);
    if (!s.ok()) s = Status::Error(FLAGS_surface + ": " + s.message());
  }
  run->solve_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run->path = StripPathToToolPath(
      run->points, cutter, FLAGS_feed,
      "tpopt stripwidth " + FLAGS_method + " torus R " + std::to_string(cutter.radius_mm) +
          " r " + std::to_string(cutter.corner_radius_mm) + " on " + run->surface.name());
  if (s.ok()) {
    // Motion on the machine only: the deviation evaluator is for ruled
    // surfaces, and the strip deviation is measured above.
    Cutter as_written = *run->path.cutter;
    s = EvaluatePath(run->path, run->machine, nullptr, as_written, deviation_options,
                     motion_options, &run->motion);
  }
  return s;
}

nlohmann::json StripReportJson(const Invocation& invocation, const TorusCutter& cutter,
                               const StripPathOptions& options, const StripRun& run,
                               const StripPathMetrics& strips) {
  nlohmann::json report = MetricsJson(run.motion);
  report["command"] = invocation.command_line;
  report["method"] = FLAGS_method;
  report["surface"] = FLAGS_surface;
  if (run.cad) report["surface_cad"] = CadInfoJson(*run.cad);
  report["machine"] = run.machine.name;
  report["cutter"] = {{"radius_mm", cutter.radius_mm},
                      {"corner_radius_mm", cutter.corner_radius_mm}};
  report["tolerance_mm"] = options.posture.tolerance_mm;
  report["strips"] = StripMetricsJson(strips);
  report["cc_points"] = PointsJson(run.points);
  report["solve_time_s"] = run.solve_s;
  return report;
}

void PrintStripSummary(const StripRun& run, const StripPathMetrics& strips) {
  const auto& a = run.motion.motion.axes[kA];
  const auto& c = run.motion.motion.axes[kC];
  std::printf(
      "%s: %zu CC points, strip width mean %.4f min %.4f mm, worst deviation %.5f mm, "
      "tool-centre fluctuation max %.5f rms %.5f mm, peak d2A/ds2 %.5f d2C/ds2 %.5f deg/mm^2, "
      "%.2f s\n",
      FLAGS_method.c_str(), run.points.size(), strips.mean_width_mm, strips.min_width_mm,
      strips.worst_deviation_mm, strips.centre_fluctuation_max_mm,
      strips.centre_fluctuation_rms_mm, a.peak_second_derivative_per_mm2 / kDegToRad,
      c.peak_second_derivative_per_mm2 / kDegToRad, run.solve_s);
}

}  // namespace

int RunStripWidth(const Invocation& invocation) {
  TorusCutter cutter;
  StripPathOptions options;
  DeviationOptions deviation_options;
  MotionOptions motion_options;
  Status s = OptionsFromFlags(&cutter, &options);
  if (s.ok()) s = MetricOptionsFromFlags(&deviation_options, &motion_options);
  if (!s.ok()) return ReportFailure("stripwidth", s);
  StripRun run;
  s = PlanStripRun(cutter, options, deviation_options, motion_options, &run);
  if (s.ok()) s = SaveToolPath(FLAGS_out, run.machine, run.path);
  const StripPathMetrics strips = s.ok() ? MeasureStripPath(run.points) : StripPathMetrics();
  if (s.ok() && !FLAGS_report.empty()) {
    s = WriteReport(FLAGS_report, StripReportJson(invocation, cutter, options, run, strips));
  }
  if (!s.ok()) return ReportFailure("stripwidth", s);
  if (!FLAGS_quiet) PrintStripSummary(run, strips);
  return kExitSuccess;
}

}  // namespace tpopt
