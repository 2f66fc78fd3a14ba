// Inline SVG charts for the HTML report: line plots and heat maps, drawn
// from C++ so the report needs no script, no network and no plotting
// runtime, and the same data always gives the same bytes.
//
// Coordinates are in SVG user units (px); data units are whatever the
// caller plots. Non-finite y values break a line (a gap, e.g. at a rapid).
#ifndef TPOPT_APPS_SVG_PLOT_H_
#define TPOPT_APPS_SVG_PLOT_H_

#include <string>
#include <vector>

namespace tpopt {

// `text` with &, <, >, " and ' replaced by entities, safe in element text
// and in quoted attributes of HTML and SVG.
std::string EscapeXml(const std::string& text);

struct PlotSeries {
  std::string label;
  std::string color;  // any CSS colour, e.g. "#1f77b4"
  std::vector<double> x, y;  // same size
};

// A horizontal line at y, e.g. an axis limit (drawn dashed, labelled).
struct PlotRule {
  std::string label;
  double y = 0.0;
};

struct LinePlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
  // Non-finite y are left out, and so are rules more than three data spans
  // beyond the data (the legend then says the rule is off scale).
  std::vector<PlotRule> rules;
  int width_px = 600;
  int height_px = 250;
};

// One <svg class="line-plot"> element: axes with ticks, one <path
// class="series"> per series (runs split by M), the rules dashed, and a
// legend. The y range covers the data and the rules drawn.
std::string RenderLinePlot(const LinePlot& plot);

struct Heatmap {
  std::string title, x_label, y_label;
  std::vector<double> x, y;     // cell centres, increasing
  std::vector<double> values;   // row-major values[ix * y.size() + iy]
  // The colour scale spans [-scale_max_abs, +scale_max_abs]: negative
  // values red, zero white, positive blue; beyond the span they saturate.
  double scale_max_abs = 1.0;
  std::string negative_label, positive_label;  // names of the two ends
  std::string units;
  int width_px = 600;
  int height_px = 220;
};

// The fill of `value` on a red-white-blue scale spanning +-max_abs, as
// "#rrggbb". max_abs <= 0 gives white.
std::string DivergingColor(double value, double max_abs);

// One <svg class="heatmap"> element: a <rect> per cell, axes and a colour
// bar labelled with the scale's ends.
std::string RenderHeatmap(const Heatmap& map);

}  // namespace tpopt

#endif  // TPOPT_APPS_SVG_PLOT_H_
