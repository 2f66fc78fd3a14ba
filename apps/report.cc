#include "apps/report.h"

#include <cstdio>

#include "apps/commands.h"
#include "apps/huge_page_malloc.h"
#include "apps/version.h"
#include "model/io/atomic_file.h"
#include "model/base/units.h"
#include "solver/smooth/smoothing_pipeline.h"

namespace tpopt {
namespace {

nlohmann::json AxisJson(const AxisMotion& m, bool rotary) {
  const double k = rotary ? kRadToDeg : 1.0;
  return {{"units", rotary ? "deg" : "mm"},
          {"peak_velocity", m.peak_velocity * k},
          {"peak_acceleration", m.peak_acceleration * k},
          {"peak_jerk", m.peak_jerk * k},
          {"peak_second_derivative_per_mm2", m.peak_second_derivative_per_mm2 * k},
          {"limit_violations", m.limit_violations}};
}

}  // namespace

nlohmann::json MetricsJson(const PathMetrics& metrics) {
  nlohmann::json j;
  j["poses"] = metrics.poses;
  j["link_moves"] = metrics.link_moves;
  if (metrics.deviation) {
    const DeviationReport& d = *metrics.deviation;
    j["max_overcut_mm"] = d.max_overcut_mm;
    j["max_undercut_mm"] = d.max_undercut_mm;
    j["rms_deviation_mm"] = d.rms_deviation_mm;
    j["max_overcut_at"] = {{"u", d.overcut_u}, {"v", d.overcut_v}};
    j["max_undercut_at"] = {{"u", d.undercut_u}, {"v", d.undercut_v}};
  } else {
    for (const char* key : {"max_overcut_mm", "max_undercut_mm", "rms_deviation_mm"}) {
      j[key] = nullptr;
    }
  }
  for (int a = 0; a < 5; ++a) {
    j[kAxisNames[a]] = AxisJson(metrics.motion.axes[a], a >= kA);
  }
  j["limit_violations"] = metrics.motion.limit_violations;
  j["worst_violation_pose"] = metrics.motion.worst_violation_pose;
  j["machining_time_s"] = metrics.motion.machining_time_s;
  j["planner_time_s"] = metrics.motion.planner_time_s;
  j["path_length_mm"] = metrics.motion.path_length_mm;
  if (!metrics.warning.empty()) j["warning"] = metrics.warning;
  return j;
}

std::string Summary(const std::string& label, const PathMetrics& m) {
  char buf[512];
  std::string out;
  if (m.deviation) {
    std::snprintf(buf, sizeof(buf),
                  "%s: %d poses, overcut %.4f mm at (u %.3f, v %.2f), undercut %.4f mm, "
                  "rms %.4f mm\n",
                  label.c_str(), m.poses, m.deviation->max_overcut_mm, m.deviation->overcut_u,
                  m.deviation->overcut_v, m.deviation->max_undercut_mm,
                  m.deviation->rms_deviation_mm);
  } else {
    std::snprintf(buf, sizeof(buf), "%s: %d poses (no surface: deviation not evaluated)\n",
                  label.c_str(), m.poses);
  }
  out += buf;
  const AxisMotion& a = m.motion.axes[kA];
  const AxisMotion& c = m.motion.axes[kC];
  std::snprintf(buf, sizeof(buf),
                "  A peak %.2f deg/s, %.1f deg/s^2 | C peak %.2f deg/s, %.1f deg/s^2 | "
                "%d limit violations | %.1f s\n",
                a.peak_velocity * kRadToDeg, a.peak_acceleration * kRadToDeg,
                c.peak_velocity * kRadToDeg, c.peak_acceleration * kRadToDeg,
                m.motion.limit_violations, m.motion.machining_time_s);
  out += buf;
  if (m.link_moves > 0) {
    std::snprintf(buf, sizeof(buf),
                  "  %d link move%s (feed >= --link_feed_ratio x the median), not smoothed "
                  "across\n",
                  m.link_moves, m.link_moves == 1 ? "" : "s");
    out += buf;
  }
  if (!m.warning.empty()) out += "  note: " + m.warning + "\n";
  return out;
}

namespace {

// A run put back as programmed: its source lines, reason and the figures
// of that reason (KeptRun).
nlohmann::json KeptRunJson(const KeptRun& k) {
  nlohmann::json j = {{"first_line", k.first_line},
                      {"last_line", k.last_line},
                      {"reason", k.reason}};
  if (k.reason == "d2") {
    j["axis"] = k.axis;
    j["input_peak_d2_deg_per_mm2"] = k.input_peak * kRadToDeg;
    j["smoothed_peak_d2_deg_per_mm2"] = k.smoothed_peak * kRadToDeg;
  } else if (k.reason == "limits") {
    j["input_limit_violations"] = k.input_violations;
    j["smoothed_limit_violations"] = k.smoothed_violations;
  } else if (k.reason == "tolerance") {
    j["u"] = k.u;
    j["v"] = k.v;
    j["worst_mm"] = k.worst_mm;
    j["input_mm"] = k.input_mm;
    j["beyond_tolerance_mm"] = k.beyond_mm;
  } else if (k.reason == "solver") {
    j["solver_message"] = k.solver_message;
  } else if (k.neighbour_line > 0) {
    j["neighbour_first_line"] = k.neighbour_line;
  }
  return j;
}

}  // namespace

nlohmann::json SmoothReportJson(const Invocation& invocation, const std::string& mode,
                                const SmoothingResult& result) {
  nlohmann::json report = MetricsJson(result.output_metrics);
  report["tpopt_version"] = kTpoptVersion;
  report["huge_page_malloc"] = HugePageMallocActive();
  report["command"] = invocation.command_line;
  report["mode"] = mode;
  report["input"] = MetricsJson(result.input_metrics);
  report["output"] = MetricsJson(result.output_metrics);
  report["output_at_input_feed"] = MetricsJson(result.output_at_input_feed);
  report["poses_in"] = result.input_metrics.poses;
  report["poses_out"] = result.output_metrics.poses;
  report["spline"] = {{"zones", result.spline.zones},
                      {"poses_in_zones", result.spline.poses_in_zones},
                      {"poses_inserted", result.spline.poses_inserted},
                      {"max_angle_change_deg", result.spline.max_angle_change_deg},
                      {"pole_crossings", result.spline.pole_crossings}};
  report["runs_kept_as_input"] = result.runs_kept_as_input;
  report["runs_kept"] = nlohmann::json::array();
  for (const KeptRun& k : result.runs_kept) report["runs_kept"].push_back(KeptRunJson(k));
  report["runs_rougher_than_programmed"] = nlohmann::json::array();
  for (const RougherRun& k : result.runs_rougher) {
    report["runs_rougher_than_programmed"].push_back(
        {{"first_line", k.first_line},
         {"last_line", k.last_line},
         {"axis", k.axis},
         {"input_peak_d2_deg_per_mm2", k.input_peak * kRadToDeg},
         {"smoothed_peak_d2_deg_per_mm2", k.smoothed_peak * kRadToDeg},
         {"input_worst_mm", k.input_worst_mm}});
  }
  const FlankRoughness& flank = result.flank_roughness;
  report["peak_d2_over_flank_path"] =
      flank.measured
          ? nlohmann::json{{"axis", flank.axis},
                           {"ratio", flank.Ratio()},
                           {"smoothed_peak_d2_deg_per_mm2", flank.smoothed_peak * kRadToDeg},
                           {"flank_path_peak_d2_deg_per_mm2", flank.flank_peak * kRadToDeg},
                           {"line", flank.line}}
          : nlohmann::json(nullptr);
  report["stiffer_solves"] = result.stiffer_solves;
  report["stiffer_solves_tips_held"] = result.stiffer_solves_tips_held;
  report["stiffer_solves_capped"] = result.stiffer_solves_capped;
  report["stiffer_solves_eased"] = result.stiffer_solves_eased;
  report["peak_deviation_rounds"] = result.peak_deviation_rounds;
  report["peak_rounds_at_milder_bound"] = result.peak_rounds_at_milder_bound;
  report["lead_poses_continued"] = result.lead_poses_continued;
  report["even_stations"] = result.even_stations;
  report["moves_per_move"] = result.moves_per_move;
  report["runs_kept_at_program_moves"] = result.runs_kept_at_program_moves;
  report["input_joint_bow_mm"] = result.input_joint_bow_mm;
  report["feed_schedule"] = {{"passes", result.feed.passes},
                             {"moves_slowed", result.feed.moves_slowed},
                             {"moves_raised", result.feed.moves_raised},
                             {"min_feed_mm_per_min", result.feed.min_feed_mm_per_min},
                             {"max_feed_mm_per_min", result.feed.max_feed_mm_per_min},
                             {"runs_retimed", result.feed.runs_retimed},
                             {"violations_left", result.feed.violations_left}};
  const HighAccuracyReport& ha = result.high_accuracy;
  report["iterations"] = ha.iterations;
  report["solve_time_s"] = ha.solve_time_s;
  if (mode == "high_accuracy") {
    report["initial_guess"] = MetricsJson(result.initial_guess_metrics);
    report["ceres"] = {{"message", ha.message},
                       {"initial_cost", ha.initial_cost},
                       {"final_cost", ha.final_cost},
                       {"final_cost_by_family", ha.final_cost_by_family},
                       {"poses_clamped_to_band", ha.poses_clamped},
                       {"pole_passages", ha.pole_passages},
                       {"pole_passages_rerouted", ha.pole_passages_rerouted},
                       {"pole_passages_in_windows", ha.pole_passages_in_windows},
                       {"solve_tolerance_mm", result.solve_tolerance_mm},
                       {"tolerance_rounds", result.tolerance_rounds},
                       {"tolerance_points", result.tolerance_points}};
  }
  return report;
}

Status WriteReport(const std::string& path, const nlohmann::json& report) {
  return WriteFileAtomically(path, report.dump(2) + "\n");
}

}  // namespace tpopt
