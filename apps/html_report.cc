#include "apps/html_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>

#include <Eigen/Core>

#include "apps/deviation_grid.h"
#include "apps/motion_profile.h"
#include "apps/svg_plot.h"
#include "apps/version.h"
#include "model/base/units.h"
#include "solver/smooth/ceres_smoother.h"

namespace tpopt {
namespace {

// Before in blue, after in orange: the two are told apart in grey scale too.
constexpr const char* kSeriesColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c"};

constexpr char kStyle[] =
    "body{font-family:sans-serif;margin:1.5em;color:#222}"
    "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:2px 8px;"
    "text-align:right}th:first-child,td:first-child{text-align:left}"
    "pre{background:#f4f4f4;padding:6px;white-space:pre-wrap}"
    ".plots{display:flex;flex-wrap:wrap;gap:8px}";

std::string Fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

// One row of the summary table: a name and its value for a path.
struct SummaryRow {
  std::string name;
  std::function<std::string(const PathMetrics&)> value;
};

std::string DeviationCell(const PathMetrics& m, double DeviationReport::*field) {
  return m.deviation ? Fixed((*m.deviation).*field, 4) : "&mdash;";
}

std::string AxisCell(const PathMetrics& m, int axis, double AxisMotion::*field) {
  return Fixed(m.motion.axes[axis].*field * kRadToDeg, 2);
}

std::vector<SummaryRow> SummaryRows() {
  std::vector<SummaryRow> rows = {
      {"poses", [](const PathMetrics& m) { return std::to_string(m.poses); }},
      {"max overcut, mm",
       [](const PathMetrics& m) { return DeviationCell(m, &DeviationReport::max_overcut_mm); }},
      {"max undercut, mm",
       [](const PathMetrics& m) { return DeviationCell(m, &DeviationReport::max_undercut_mm); }},
      {"RMS deviation, mm",
       [](const PathMetrics& m) { return DeviationCell(m, &DeviationReport::rms_deviation_mm); }},
  };
  for (int axis : {kA, kC}) {
    const std::string name = kAxisNames[axis];
    rows.push_back({name + " peak velocity, deg/s", [axis](const PathMetrics& m) {
                      return AxisCell(m, axis, &AxisMotion::peak_velocity);
                    }});
    rows.push_back({name + " peak acceleration, deg/s&sup2;", [axis](const PathMetrics& m) {
                      return AxisCell(m, axis, &AxisMotion::peak_acceleration);
                    }});
    rows.push_back({name + " peak jerk, deg/s&sup3;", [axis](const PathMetrics& m) {
                      return AxisCell(m, axis, &AxisMotion::peak_jerk);
                    }});
  }
  rows.push_back({"limit violations", [](const PathMetrics& m) {
                    return std::to_string(m.motion.limit_violations);
                  }});
  rows.push_back({"machining time, s",
                  [](const PathMetrics& m) { return Fixed(m.motion.machining_time_s, 2); }});
  rows.push_back({"tip path length, mm",
                  [](const PathMetrics& m) { return Fixed(m.motion.path_length_mm, 2); }});
  return rows;
}

std::string SummaryTable(const std::vector<ReportedPath>& paths) {
  std::string out = "<table class=\"summary\">\n<tr><th>metric</th>";
  for (const ReportedPath& p : paths) out += "<th>" + EscapeXml(p.label) + "</th>";
  out += "</tr>\n";
  for (const SummaryRow& row : SummaryRows()) {
    out += "<tr><td>" + row.name + "</td>";
    for (const ReportedPath& p : paths) out += "<td>" + row.value(*p.metrics) + "</td>";
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

// What one plot shows of each path's profile, and the limit it is held to.
struct Quantity {
  std::string name, units;
  std::function<const std::vector<double>&(const MotionProfile&)> x, y;
  std::function<std::vector<PlotRule>(const AxisLimits&)> rules;
};

std::vector<PlotRule> Symmetric(double limit_rad) {
  return {{"machine limit", limit_rad * kRadToDeg}, {"machine limit", -limit_rad * kRadToDeg}};
}

std::vector<Quantity> Quantities(int k) {
  return {
      {"angle", "deg", [](const MotionProfile& p) -> const auto& { return p.s_pose_mm; },
       [k](const MotionProfile& p) -> const auto& { return p.angle_deg[k]; },
       [](const AxisLimits& l) {
         return std::vector<PlotRule>{{"travel limit", l.max * kRadToDeg},
                                      {"travel limit", l.min * kRadToDeg}};
       }},
      {"velocity", "deg/s", [](const MotionProfile& p) -> const auto& { return p.s_segment_mm; },
       [k](const MotionProfile& p) -> const auto& { return p.velocity_deg_s[k]; },
       [](const AxisLimits& l) { return Symmetric(l.max_velocity); }},
      {"acceleration", "deg/s\u00b2",
       [](const MotionProfile& p) -> const auto& { return p.s_pose_mm; },
       [k](const MotionProfile& p) -> const auto& { return p.acceleration_deg_s2[k]; },
       [](const AxisLimits& l) { return Symmetric(l.max_acceleration); }},
  };
}

std::string MotionPlots(const HtmlReportInputs& inputs,
                        const std::vector<MotionProfile>& profiles) {
  std::string out = "<h2>Rotary axes against tip path length</h2>\n<div class=\"plots\">\n";
  for (int k = 0; k < 2; ++k) {
    const int axis = k == 0 ? kA : kC;
    for (const Quantity& q : Quantities(k)) {
      LinePlot plot;
      plot.title = std::string(kAxisNames[axis]) + " " + q.name;
      plot.x_label = "tip path length, mm";
      plot.y_label = q.name + ", " + q.units;
      plot.rules = q.rules(inputs.machine->limits[axis]);
      for (size_t i = 0; i < profiles.size(); ++i) {
        plot.series.push_back({inputs.paths[i].label, kSeriesColours[i % 3], q.x(profiles[i]),
                               q.y(profiles[i])});
      }
      out += RenderLinePlot(plot);
    }
  }
  return out + "</div>\n";
}

// The deviation maps share one colour scale so before and after compare.
std::string DeviationMaps(const std::vector<ReportedPath>& paths) {
  std::vector<std::pair<std::string, SurfaceGrid>> grids;
  double max_abs = 0.0;
  for (const ReportedPath& p : paths) {
    std::optional<SurfaceGrid> grid = DeviationGridOf(*p.metrics);
    if (!grid) continue;
    for (double d : grid->deviation_mm) max_abs = std::max(max_abs, std::abs(d));
    grids.emplace_back(p.label, std::move(*grid));
  }
  if (grids.empty()) return "";
  std::string out = "<h2>Deviation over the surface</h2>\n<div class=\"plots\">\n";
  for (auto& [label, grid] : grids) {
    Heatmap map;
    map.title = "deviation, " + label;
    map.x_label = "u (along the rails)";
    map.y_label = "v (along the ruling)";
    map.x = grid.u;
    map.y = grid.v;
    map.values = grid.deviation_mm;
    map.scale_max_abs = max_abs;
    map.negative_label = "overcut";
    map.positive_label = "undercut";
    map.units = "mm";
    out += RenderHeatmap(map);
  }
  return out + "</div>\n";
}

std::string Versions() {
  const std::string eigen = std::to_string(EIGEN_WORLD_VERSION) + "." +
                            std::to_string(EIGEN_MAJOR_VERSION) + "." +
                            std::to_string(EIGEN_MINOR_VERSION);
  return std::string("<table class=\"versions\">\n<tr><td>tpopt</td><td>") + kTpoptVersion +
         "</td></tr>\n<tr><td>Ceres Solver</td><td>" + EscapeXml(CeresVersion()) +
         "</td></tr>\n<tr><td>Eigen</td><td>" + eigen +
         "</td></tr>\n<tr><td>compiler</td><td>" + EscapeXml(__VERSION__) +
         "</td></tr>\n</table>\n";
}

std::string ControllerSection(const HtmlReportInputs& inputs) {
  if (inputs.controller == nullptr || inputs.paths.empty()) return "";
  return ControllerRunHtml(*inputs.controller,
                           inputs.paths.back().metrics->motion.planner_time_s);
}

}  // namespace

Status RenderHtmlReport(const HtmlReportInputs& inputs, std::string* html) {
  std::vector<MotionProfile> profiles(inputs.paths.size());
  for (size_t i = 0; i < inputs.paths.size(); ++i) {
    Status s = ComputeMotionProfile(*inputs.machine, *inputs.paths[i].path,
                                    inputs.default_feed_mm_per_min, &profiles[i]);
    if (!s.ok()) return Status::Error(inputs.paths[i].label + " path: " + s.message());
  }
  const std::string title = EscapeXml(inputs.title);
  *html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + title +
          "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + title + "</h1>\n" +
          "<h2>Summary</h2>\n" + SummaryTable(inputs.paths) + MotionPlots(inputs, profiles) +
          DeviationMaps(inputs.paths) + ControllerSection(inputs) + "<h2>Command line</h2>\n<pre>" +
          EscapeXml(inputs.command_line) + "</pre>\n<h2>Versions</h2>\n" + Versions() +
          "</body>\n</html>\n";
  return Status::Ok();
}

}  // namespace tpopt
