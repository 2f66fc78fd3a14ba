#include "apps/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace tpopt {
namespace {

// Room around the plotting area for tick labels, titles and the legend.
constexpr double kLeft = 64, kRight = 150, kTop = 26, kBottom = 40;
constexpr int kTargetTicks = 5;
// A rule farther than this many data spans beyond the data is off scale.
constexpr double kRuleReach = 3.0;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // An empty or zero-width range would divide by zero when mapped.
  Range Padded() const {
    Range r = *this;
    if (!(r.lo <= r.hi)) return Range{0.0, 1.0};
    if (r.hi - r.lo < 1e-12 * std::max(1.0, std::abs(r.hi))) {
      const double pad = std::max(1e-9, 0.1 * std::abs(r.hi));
      r.lo -= pad;
      r.hi += pad;
    }
    return r;
  }
};

// Linear map from a data range onto a pixel span (flipped for y).
struct Scale {
  Range data;
  double px0, px1;
  double operator()(double v) const {
    return px0 + (v - data.lo) / (data.hi - data.lo) * (px1 - px0);
  }
};

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string TickLabel(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

// A 1, 2 or 5 times a power of ten near span / kTargetTicks.
double NiceStep(double span) {
  const double raw = span / kTargetTicks;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw) return m * power;
  }
  return 10.0 * power;
}

std::vector<double> Ticks(const Range& r) {
  const double step = NiceStep(r.hi - r.lo);
  std::vector<double> ticks;
  for (double t = std::ceil(r.lo / step) * step; t <= r.hi + 1e-9 * step; t += step) {
    ticks.push_back(t);
  }
  return ticks;
}

std::string Text(double x, double y, const std::string& anchor, const std::string& text,
                 const std::string& extra = "") {
  return "<text x=\"" + Num(x) + "\" y=\"" + Num(y) + "\" text-anchor=\"" + anchor + "\"" +
         extra + ">" + EscapeXml(text) + "</text>\n";
}

// Frame, ticks, tick labels and axis titles around the plotting area.
std::string Axes(const Scale& sx, const Scale& sy, const std::string& title,
                 const std::string& x_label, const std::string& y_label) {
  std::string out = "<path class=\"frame\" fill=\"none\" stroke=\"#444\" d=\"M" + Num(sx.px0) +
                    "," + Num(sy.px1) + "V" + Num(sy.px0) + "H" + Num(sx.px1) + "\"/>\n";
  for (double t : Ticks(sx.data)) {
    out += "<path class=\"tick\" stroke=\"#ccc\" d=\"M" + Num(sx(t)) + "," + Num(sy.px0) + "V" +
           Num(sy.px1) + "\"/>\n";
    out += Text(sx(t), sy.px0 + 14, "middle", TickLabel(t));
  }
  for (double t : Ticks(sy.data)) {
    out += "<path class=\"tick\" stroke=\"#ccc\" d=\"M" + Num(sx.px0) + "," + Num(sy(t)) + "H" +
           Num(sx.px1) + "\"/>\n";
    out += Text(sx.px0 - 4, sy(t) + 4, "end", TickLabel(t));
  }
  out += Text(0.5 * (sx.px0 + sx.px1), sy.px0 + 32, "middle", x_label);
  const std::string y_mid = Num(0.5 * (sy.px0 + sy.px1));
  out += Text(14, 0.5 * (sy.px0 + sy.px1), "middle", y_label,
              " transform=\"rotate(-90 14 " + y_mid + ")\"");
  out += Text(sx.px0, 16, "start", title, " font-weight=\"bold\"");
  return out;
}

std::string SvgOpen(const std::string& css_class, int width, int height,
                    const std::string& title) {
  return "<svg class=\"" + css_class + "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
         std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" viewBox=\"0 0 " +
         std::to_string(width) + " " + std::to_string(height) +
         "\" font-family=\"sans-serif\" font-size=\"11\">\n<title>" + EscapeXml(title) +
         "</title>\n";
}

// Path data of one series; a non-finite y ends a run and the next finite
// point starts a new one with M.
std::string SeriesPathData(const PlotSeries& s, const Scale& sx, const Scale& sy) {
  std::string d;
  bool pen_down = false;
  for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      pen_down = false;
      continue;
    }
    d += (pen_down ? "L" : "M") + Num(sx(s.x[i])) + "," + Num(sy(s.y[i]));
    pen_down = true;
  }
  return d;
}

std::string LegendEntry(double x, double y, const std::string& color, const std::string& label,
                        bool dashed) {
  return "<path stroke=\"" + color + "\" stroke-width=\"2\"" +
         (dashed ? " stroke-dasharray=\"5,3\"" : "") + " d=\"M" + Num(x) + "," + Num(y) +
         "h18\"/>\n" +
         Text(x + 22, y + 4, "start", label);
}

// The finite rules near enough to the data to draw without flattening
// it: a C travel of +-100 turns beside 20 degrees of motion would leave the
// data a flat line, so such a rule is named in the legend instead.
std::vector<PlotRule> RulesOnScale(const std::vector<PlotRule>& rules, const Range& data) {
  const Range padded = data.Padded();
  const double reach = kRuleReach * (padded.hi - padded.lo);
  std::vector<PlotRule> shown;
  for (const PlotRule& r : rules) {
    if (std::isfinite(r.y) && r.y >= padded.lo - reach && r.y <= padded.hi + reach) {
      shown.push_back(r);
    }
  }
  return shown;
}

}  // namespace

std::string EscapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string RenderLinePlot(const LinePlot& plot) {
  Range xr, yr;
  for (const PlotSeries& s : plot.series) {
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      xr.Add(s.x[i]);
      yr.Add(s.y[i]);
    }
  }
  const std::vector<PlotRule> shown = RulesOnScale(plot.rules, yr);
  for (const PlotRule& r : shown) yr.Add(r.y);
  const Scale sx{xr.Padded(), kLeft, plot.width_px - kRight};
  const Scale sy{yr.Padded(), plot.height_px - kBottom, kTop};
  std::string out = SvgOpen("line-plot", plot.width_px, plot.height_px, plot.title);
  out += Axes(sx, sy, plot.title, plot.x_label, plot.y_label);
  double legend_y = kTop + 6;
  const double legend_x = plot.width_px - kRight + 10;
  for (const PlotRule& r : shown) {
    out += "<path class=\"rule\" stroke=\"#d62728\" stroke-dasharray=\"5,3\" d=\"M" + Num(sx.px0) +
           "," + Num(sy(r.y)) + "H" + Num(sx.px1) + "\"/>\n";
  }
  for (const PlotSeries& s : plot.series) {
    out += "<path class=\"series\" fill=\"none\" stroke=\"" + s.color +
           "\" stroke-width=\"1.5\" d=\"" + SeriesPathData(s, sx, sy) + "\"/>\n";
    out += LegendEntry(legend_x, legend_y, s.color, s.label, false);
    legend_y += 16;
  }
  if (!shown.empty()) {
    out += LegendEntry(legend_x, legend_y, "#d62728", shown.front().label, true);
  } else if (std::any_of(plot.rules.begin(), plot.rules.end(),
                         [](const PlotRule& r) { return std::isfinite(r.y); })) {
    out += LegendEntry(legend_x, legend_y, "#d62728",
                       plot.rules.front().label + " off scale", true);
  }
  return out + "</svg>\n";
}

std::string DivergingColor(double value, double max_abs) {
  double t = max_abs > 0 && std::isfinite(value) ? value / max_abs : 0.0;
  t = std::clamp(t, -1.0, 1.0);
  // White at zero, towards red (overcut, negative) or blue (positive).
  const double fade = 1.0 - std::abs(t);
  const int r = static_cast<int>(std::lround(t < 0 ? 214 + 41 * fade : 31 + 224 * fade));
  const int g = static_cast<int>(std::lround(t < 0 ? 39 + 216 * fade : 119 + 136 * fade));
  const int b = static_cast<int>(std::lround(t < 0 ? 40 + 215 * fade : 180 + 75 * fade));
  char buf[8];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", r, g, b);
  return buf;
}

namespace {

// Cell edges around increasing centres: midpoints, the ends half a step out.
std::vector<double> CellEdges(const std::vector<double>& centres) {
  const size_t n = centres.size();
  std::vector<double> edges(n + 1);
  if (n == 1) return {centres[0] - 0.5, centres[0] + 0.5};
  for (size_t i = 1; i < n; ++i) edges[i] = 0.5 * (centres[i - 1] + centres[i]);
  edges[0] = centres[0] - (edges[1] - centres[0]);
  edges[n] = centres[n - 1] + (centres[n - 1] - edges[n - 1]);
  return edges;
}

std::string ColourBar(const Heatmap& map, double x, double top, double bottom) {
  constexpr int kSteps = 20;
  std::string out;
  const double h = (bottom - top) / kSteps;
  for (int k = 0; k < kSteps; ++k) {
    // Top of the bar is the positive end.
    const double value = map.scale_max_abs * (1.0 - 2.0 * (k + 0.5) / kSteps);
    out += "<rect x=\"" + Num(x) + "\" y=\"" + Num(top + k * h) + "\" width=\"14\" height=\"" +
           Num(h + 0.5) + "\" fill=\"" + DivergingColor(value, map.scale_max_abs) + "\"/>\n";
  }
  out += Text(x + 18, top + 8, "start", "+" + TickLabel(map.scale_max_abs) + " " + map.units);
  out += Text(x + 18, top + 20, "start", map.positive_label);
  out += Text(x + 18, 0.5 * (top + bottom) + 4, "start", "0");
  out += Text(x + 18, bottom - 12, "start", map.negative_label);
  out += Text(x + 18, bottom, "start", "-" + TickLabel(map.scale_max_abs) + " " + map.units);
  return out;
}

}  // namespace

std::string RenderHeatmap(const Heatmap& map) {
  const std::vector<double> xe = CellEdges(map.x), ye = CellEdges(map.y);
  const Scale sx{Range{xe.front(), xe.back()}.Padded(), kLeft, map.width_px - kRight};
  const Scale sy{Range{ye.front(), ye.back()}.Padded(), map.height_px - kBottom, kTop};
  std::string out = SvgOpen("heatmap", map.width_px, map.height_px, map.title);
  out += "<g class=\"cells\" shape-rendering=\"crispEdges\">\n";
  for (size_t ix = 0; ix < map.x.size(); ++ix) {
    for (size_t iy = 0; iy < map.y.size(); ++iy) {
      const double value = map.values[ix * map.y.size() + iy];
      // Half a pixel of overlap hides the seams between neighbouring cells.
      out += "<rect x=\"" + Num(sx(xe[ix])) + "\" y=\"" + Num(sy(ye[iy + 1])) + "\" width=\"" +
             Num(sx(xe[ix + 1]) - sx(xe[ix]) + 0.5) + "\" height=\"" +
             Num(sy(ye[iy]) - sy(ye[iy + 1]) + 0.5) + "\" fill=\"" +
             DivergingColor(value, map.scale_max_abs) + "\"/>\n";
    }
  }
  out += "</g>\n";
  out += Axes(sx, sy, map.title, map.x_label, map.y_label);
  out += ColourBar(map, map.width_px - kRight + 10, kTop, map.height_px - kBottom);
  return out + "</svg>\n";
}

}  // namespace tpopt
