// The report JSON (README.md, "What the report measures") and the short human summary.
#ifndef TPOPT_APPS_REPORT_H_
#define TPOPT_APPS_REPORT_H_

#include <string>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "model/eval/path_metrics.h"
#include "solver/smooth/smoothing_pipeline.h"
#include "model/base/status.h"

namespace tpopt {

// Metrics of one path: max_overcut_mm, max_undercut_mm, rms_deviation_mm
// (null without a surface) with where they occur, per axis A, C, X, Y, Z
// its peak_velocity, peak_acceleration, peak_jerk (deg or mm per s, s^2,
// s^3), peak second derivative over arc length and limit_violations, the
// total limit_violations, machining_time_s, path length and poses.
nlohmann::json MetricsJson(const PathMetrics& metrics);

// A few lines for stderr/stdout: deviation, peak A/C motion, violations.
std::string Summary(const std::string& label, const PathMetrics& metrics);

// The smooth report: the output's metrics at the top level, then `input`,
// `output`, `output_at_input_feed`, `initial_guess` (high accuracy), and
// the spline, Ceres and feed-schedule reports.
nlohmann::json SmoothReportJson(const Invocation& invocation, const std::string& mode,
                                const SmoothingResult& result);

// Writes `report` (pretty-printed) whole or not at all.
Status WriteReport(const std::string& path, const nlohmann::json& report);

}  // namespace tpopt

#endif  // TPOPT_APPS_REPORT_H_
