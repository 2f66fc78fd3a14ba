// tpopt stripwidth: a strip-width machining pass with a torus cutter over a
// bicubic surface, positioned by Sturz's method, the multi-point method or
// mid-point error control (solver/tool_posture.h), written as a CL path
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
#include "model/freeform_surface.h"
#include "model/path_metrics.h"
#include "model/units.h"
#include "solver/strip_path.h"
#include "solver/strip_path_metrics.h"

namespace tpopt {
namespace {

// "torus:R,r" in mm.
Status ParseTorusFlag(const std::string& text, TorusCutter* cutter) {
  const std::string prefix = "torus:";
  const std::string usage = "--cutter=" + text + " must be torus:R,r (mm), e.g. torus:8,2";
  if (text.compare(0, prefix.size(), prefix) != 0) return Status::Usage(usage);
  const char* begin = text.c_str() + prefix.size();
  char* end = nullptr;
  cutter->radius_mm = std::strtod(begin, &end);
  if (end == begin || *end != ',') return Status::Usage(usage);
  const char* second = end + 1;
  cutter->corner_radius_mm = std::strtod(second, &end);
  if (end == second || *end != '\0') return Status::Usage(usage);
  std::string why;
  if (!cutter->IsValid(&why)) return Status::Usage("--cutter: " + why);
  return Status::Ok();
}

Status MethodFromFlag(const std::string& name, PostureMethod* method) {
  if (name == "sturz") {
    *method = PostureMethod::kSturz;
  } else if (name == "mpm") {
    *method = PostureMethod::kMultiPoint;
  } else if (name == "mpec") {
    *method = PostureMethod::kMidPointErrorControl;
  } else {
    return Status::Usage("--method=" + name + " must be sturz, mpm or mpec");
  }
  return Status::Ok();
}

Status OptionsFromFlags(TorusCutter* cutter, StripPathOptions* options) {
  RETURN_IF_ERROR(Require(FLAGS_surface, "surface"));
  RETURN_IF_ERROR(Require(FLAGS_out, "out"));
  RETURN_IF_ERROR(Require(FLAGS_cutter, "cutter"));
  RETURN_IF_ERROR(CheckGcodeFlags());
  RETURN_IF_ERROR(ParseTorusFlag(FLAGS_cutter, cutter));
  RETURN_IF_ERROR(MethodFromFlag(FLAGS_method, &options->method));
  PostureOptions& posture = options->posture;
  posture.tolerance_mm = FLAGS_tolerance_mm;
  posture.sturz_lead_rad = FLAGS_lead_deg * kDegToRad;
  posture.min_lead_rad = FLAGS_min_lead_deg * kDegToRad;
  posture.max_lead_rad = FLAGS_max_lead_deg * kDegToRad;
  posture.max_tilt_rad = FLAGS_max_tilt_deg * kDegToRad;
  options->poses = FLAGS_cc_points;
  options->path_v = FLAGS_path_v;
  options->samples_per_side = FLAGS_section_samples;
  std::string why;
  if (!options->IsValid(&why)) return Status::Usage(why);
  if (!(FLAGS_feed > 0.0)) return Status::Usage("--feed must be > 0");
  return Status::Ok();
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

}  // namespace

int RunStripWidth(const Invocation& invocation) {
  TorusCutter cutter;
  StripPathOptions options;
  DeviationOptions deviation_options;
  MotionOptions motion_options;
  Status s = OptionsFromFlags(&cutter, &options);
  if (s.ok()) s = MetricOptionsFromFlags(&deviation_options, &motion_options);
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt stripwidth: %s\n", s.message().c_str());
    return ExitCodeOf(s);
  }
  FreeformSurface surface;
  Machine machine;
  std::vector<StripPoint> points;
  const auto start = std::chrono::steady_clock::now();
  std::optional<CadSurfaceInfo> cad;
  s = LoadFreeformSurface(FLAGS_surface, &surface, &cad);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &machine);
  if (s.ok()) {
    s = PlanStripPath(surface, cutter, options, &points);
    if (!s.ok()) s = Status::Error(FLAGS_surface + ": " + s.message());
  }
  const double solve_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const ToolPath path = StripPathToToolPath(
      points, cutter, FLAGS_feed,
      "tpopt stripwidth " + FLAGS_method + " torus R " + std::to_string(cutter.radius_mm) +
          " r " + std::to_string(cutter.corner_radius_mm) + " on " + surface.name());
  PathMetrics motion;
  if (s.ok()) {
    // Motion on the machine only: the deviation evaluator is for ruled
    // surfaces, and the strip deviation is measured above.
    Cutter as_written = *path.cutter;
    s = EvaluatePath(path, machine, nullptr, as_written, deviation_options, motion_options,
                     &motion);
  }
  if (s.ok()) s = SaveToolPath(FLAGS_out, machine, path);
  const StripPathMetrics strips = s.ok() ? MeasureStripPath(points) : StripPathMetrics();
  if (s.ok() && !FLAGS_report.empty()) {
    nlohmann::json report = MetricsJson(motion);
    report["command"] = invocation.command_line;
    report["method"] = FLAGS_method;
    report["surface"] = FLAGS_surface;
    if (cad) report["surface_cad"] = CadInfoJson(*cad);
    report["machine"] = machine.name;
    report["cutter"] = {{"radius_mm", cutter.radius_mm},
                        {"corner_radius_mm", cutter.corner_radius_mm}};
    report["tolerance_mm"] = options.posture.tolerance_mm;
    report["strips"] = StripMetricsJson(strips);
    report["cc_points"] = PointsJson(points);
    report["solve_time_s"] = solve_s;
    s = WriteReport(FLAGS_report, report);
  }
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt stripwidth: %s\n", s.message().c_str());
    return ExitCodeOf(s);
  }
  if (!FLAGS_quiet) {
    const auto& a = motion.motion.axes[kA];
    const auto& c = motion.motion.axes[kC];
    std::printf(
        "%s: %zu CC points, strip width mean %.4f min %.4f mm, worst deviation %.5f mm, "
        "tool-centre fluctuation max %.5f rms %.5f mm, peak d2A/ds2 %.5f d2C/ds2 %.5f deg/mm^2, "
        "%.2f s\n",
        FLAGS_method.c_str(), points.size(), strips.mean_width_mm, strips.min_width_mm,
        strips.worst_deviation_mm, strips.centre_fluctuation_max_mm,
        strips.centre_fluctuation_rms_mm, a.peak_second_derivative_per_mm2 / kDegToRad,
        c.peak_second_derivative_per_mm2 / kDegToRad, solve_s);
  }
  return kExitSuccess;
}

}  // namespace tpopt
