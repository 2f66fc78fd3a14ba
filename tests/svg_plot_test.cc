#include "apps/svg_plot.h"

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace tpopt {
namespace {

// The d attributes of every <path class="series">, in order.
std::vector<std::string> SeriesPaths(const std::string& svg) {
  static const std::regex kSeries("<path class=\"series\"[^>]* d=\"([^\"]*)\"");
  std::vector<std::string> d;
  for (std::sregex_iterator it(svg.begin(), svg.end(), kSeries), end; it != end; ++it) {
    d.push_back((*it)[1]);
  }
  return d;
}

LinePlot Ramp(int points) {
  LinePlot plot;
  plot.title = "ramp";
  PlotSeries s{"ramp", "#000000", {}, {}};
  for (int i = 0; i < points; ++i) {
    s.x.push_back(i);
    s.y.push_back(2.0 * i);
  }
  plot.series.push_back(s);
  return plot;
}

TEST(SvgPlotTest, EscapesEveryMarkupCharacter) {
  EXPECT_EQ(EscapeXml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(EscapeXml("plain 1.5 mm"), "plain 1.5 mm");
}

TEST(SvgPlotTest, TitlesAndLabelsAreEscaped) {
  LinePlot plot = Ramp(3);
  plot.title = "<script>alert(1)</script>";
  plot.series[0].label = "a & b";
  const std::string svg = RenderLinePlot(plot);
  EXPECT_EQ(svg.find("<script>"), std::string::npos);
  EXPECT_NE(svg.find("&lt;script&gt;alert(1)&lt;/script&gt;"), std::string::npos);
  EXPECT_NE(svg.find("a &amp; b"), std::string::npos);
}

TEST(SvgPlotTest, OneSeriesIsOnePathThroughEveryPointCornerToCorner) {
  const int n = 11;
  const LinePlot plot = Ramp(n);
  const std::vector<std::string> d = SeriesPaths(RenderLinePlot(plot));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(testing::CountOccurrences(d[0], "M"), 1);
  EXPECT_EQ(testing::CountOccurrences(d[0], "L"), n - 1);
  // The data's corners land on the plotting area's corners: x from the left
  // margin to the width less the legend, y from the bottom margin up to the
  // top margin (the layout constants of svg_plot.cc: 64, 150, 40, 26).
  const std::string left = std::to_string(64), right = std::to_string(plot.width_px - 150);
  const std::string bottom = std::to_string(plot.height_px - 40), top = std::to_string(26);
  EXPECT_EQ(d[0].rfind("M" + left + ".0," + bottom + ".0", 0), 0u) << d[0];
  EXPECT_NE(d[0].find("L" + right + ".0," + top + ".0"), std::string::npos) << d[0];
}

TEST(SvgPlotTest, NonFiniteValuesBreakTheLine) {
  LinePlot plot = Ramp(9);
  plot.series[0].y[3] = std::numeric_limits<double>::quiet_NaN();
  plot.series[0].y[6] = std::numeric_limits<double>::infinity();
  const std::vector<std::string> d = SeriesPaths(RenderLinePlot(plot));
  ASSERT_EQ(d.size(), 1u);
  // Three runs: 0-2, 4-5, 7-8 -> three M and 2 + 1 + 1 L.
  EXPECT_EQ(testing::CountOccurrences(d[0], "M"), 3);
  EXPECT_EQ(testing::CountOccurrences(d[0], "L"), 4);
  EXPECT_EQ(d[0].find("nan"), std::string::npos);
  EXPECT_EQ(d[0].find("inf"), std::string::npos);
}

TEST(SvgPlotTest, RulesNearTheDataAreDrawnFarOnesNamedOffScale) {
  LinePlot plot = Ramp(5);  // y in [0, 8]
  plot.rules = {{"limit", 10.0}, {"limit", -10.0}};
  std::string svg = RenderLinePlot(plot);
  EXPECT_EQ(testing::CountOccurrences(svg, "class=\"rule\""), 2);
  EXPECT_EQ(svg.find("off scale"), std::string::npos);

  plot.rules = {{"travel", 36000.0}, {"travel", -36000.0}};
  svg = RenderLinePlot(plot);
  EXPECT_EQ(testing::CountOccurrences(svg, "class=\"rule\""), 0);
  EXPECT_NE(svg.find("travel off scale"), std::string::npos);

  plot.rules = {{"none", std::numeric_limits<double>::infinity()}};
  svg = RenderLinePlot(plot);
  EXPECT_EQ(testing::CountOccurrences(svg, "class=\"rule\""), 0);
  EXPECT_EQ(svg.find("off scale"), std::string::npos);
}

TEST(SvgPlotTest, DivergingColourIsWhiteAtZeroAndSaturatesAtTheEnds) {
  EXPECT_EQ(DivergingColor(0.0, 1.0), "#ffffff");
  EXPECT_EQ(DivergingColor(-1.0, 1.0), "#d62728");  // overcut end
  EXPECT_EQ(DivergingColor(1.0, 1.0), "#1f77b4");   // undercut end
  EXPECT_EQ(DivergingColor(-5.0, 1.0), DivergingColor(-1.0, 1.0));
  EXPECT_EQ(DivergingColor(0.3, 0.0), "#ffffff");
  // Halfway is between white and the end, channel by channel.
  const std::string half = DivergingColor(-0.5, 1.0);
  EXPECT_GT(std::stoi(half.substr(3, 2), nullptr, 16), 0x27);
  EXPECT_LT(std::stoi(half.substr(3, 2), nullptr, 16), 0xff);
}

TEST(SvgPlotTest, HeatmapHasOneCellPerValueWithItsColour) {
  Heatmap map;
  map.title = "map";
  map.x = {0.0, 0.5, 1.0};
  map.y = {0.0, 1.0};
  map.values = {-2.0, 0.0, 1.0, 2.0, 0.0, -1.0};
  map.scale_max_abs = 2.0;
  map.negative_label = "overcut";
  map.positive_label = "undercut";
  const std::string svg = RenderHeatmap(map);
  const size_t cells = svg.find("<g class=\"cells\""), cells_end = svg.find("</g>");
  ASSERT_NE(cells, std::string::npos);
  const std::string grid = svg.substr(cells, cells_end - cells);
  EXPECT_EQ(testing::CountOccurrences(grid, "<rect"), 6);
  EXPECT_EQ(testing::CountOccurrences(grid, "fill=\"" + DivergingColor(-2.0, 2.0) + "\""), 1);
  EXPECT_EQ(testing::CountOccurrences(grid, "fill=\"#ffffff\""), 2);
  EXPECT_NE(svg.find("overcut"), std::string::npos);
  EXPECT_NE(svg.find("undercut"), std::string::npos);
}

}  // namespace
}  // namespace tpopt
