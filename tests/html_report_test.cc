#include "apps/html_report.h"

#include <cstdio>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "model/io/json_io.h"
#include "model/path/path_generator.h"
#include "solver/smooth/ceres_smoother.h"
#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::SourcePath;

std::string Fixed4(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4f", v);
  return buf;
}

class HtmlReportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ReadSurfaceJson(SourcePath("data/surfaces/hypar.json"), &surface_).ok());
    ASSERT_TRUE(
        ReadMachineJson(SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json"), &machine_).ok());
    FlankPathOptions options;
    options.poses = 40;
    ASSERT_TRUE(GenerateFlankPath(surface_, options, &after_).ok());
    options.uv_distortion = 0.03;
    options.axis_noise_deg = 0.3;
    ASSERT_TRUE(GenerateFlankPath(surface_, options, &before_).ok());
    deviation_.samples_u = 30;
    deviation_.samples_v = 5;
  }

  PathMetrics Evaluate(const ToolPath& path, const RuledSurface* surface) {
    PathMetrics metrics;
    EXPECT_TRUE(EvaluatePath(path, machine_, surface, *path.cutter, deviation_, MotionOptions(),
                             &metrics)
                    .ok());
    return metrics;
  }

  std::string Render(const RuledSurface* surface, PathMetrics* before, PathMetrics* after) {
    *before = Evaluate(before_, surface);
    *after = Evaluate(after_, surface);
    HtmlReportInputs inputs;
    inputs.title = "tpopt smooth of <cam.cls>";
    inputs.command_line = "tpopt smooth --in=a&b.cls --html=\"r.html\"";
    inputs.paths = {{"before", &before_, before}, {"after", &after_, after}};
    inputs.machine = &machine_;
    std::string html;
    EXPECT_TRUE(RenderHtmlReport(inputs, &html).ok());
    return html;
  }

  RuledSurface surface_;
  Machine machine_;
  ToolPath before_, after_;
  DeviationOptions deviation_;
};

TEST_F(HtmlReportTest, HoldsTheMotionPlotsDeviationMapsAndSummary) {
  PathMetrics before, after;
  const std::string html = Render(&surface_, &before, &after);
  // A and C: angle, velocity, acceleration; each with both paths drawn.
  EXPECT_EQ(testing::CountOccurrences(html, "<svg class=\"line-plot\""), 6);
  EXPECT_EQ(testing::CountOccurrences(html, "<path class=\"series\""), 12);
  // Every series is drawn through the poses: 40 poses give at least 30
  // points even where the velocity or acceleration has gaps.
  const std::regex series_path("<path class=\"series\"[^>]* d=\"([^\"]*)\"");
  for (std::sregex_iterator it(html.begin(), html.end(), series_path), end; it != end; ++it) {
    EXPECT_GE(testing::CountOccurrences((*it)[1], "L"), 30) << (*it)[1];
  }
  // The sim machine limits A's travel, velocity and acceleration.
  EXPECT_GE(testing::CountOccurrences(html, "class=\"rule\""), 2);
  // One deviation map per path, one cell per grid point.
  EXPECT_EQ(testing::CountOccurrences(html, "<svg class=\"heatmap\""), 2);
  const size_t cells = deviation_.samples_u * deviation_.samples_v;
  size_t rects = 0;
  for (size_t at = html.find("<g class=\"cells\""); at != std::string::npos;
       at = html.find("<g class=\"cells\"", at + 1)) {
    rects += testing::CountOccurrences(html.substr(at, html.find("</g>", at) - at), "<rect");
  }
  EXPECT_EQ(rects, 2 * cells);
  // The summary shows each path's own numbers.
  EXPECT_NE(html.find("<th>before</th><th>after</th>"), std::string::npos);
  EXPECT_NE(html.find("<td>max overcut, mm</td><td>" + Fixed4(before.deviation->max_overcut_mm) +
                      "</td><td>" + Fixed4(after.deviation->max_overcut_mm) + "</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td>limit violations</td><td>" +
                      std::to_string(before.motion.limit_violations) + "</td><td>" +
                      std::to_string(after.motion.limit_violations) + "</td>"),
            std::string::npos);
  EXPECT_NE(html.find(CeresVersion()), std::string::npos);
}

TEST_F(HtmlReportTest, EscapesTheCommandLineAndTitle) {
  PathMetrics before, after;
  const std::string html = Render(&surface_, &before, &after);
  EXPECT_NE(html.find("tpopt smooth --in=a&amp;b.cls --html=&quot;r.html&quot;"),
            std::string::npos);
  EXPECT_NE(html.find("<title>tpopt smooth of &lt;cam.cls&gt;</title>"), std::string::npos);
  EXPECT_EQ(html.find("<cam.cls>"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // no script, no network
  EXPECT_EQ(html.find("http://", html.find("<body>")), html.find("http://www.w3.org/2000/svg"));
}

TEST_F(HtmlReportTest, WithoutASurfaceThereIsNoDeviationMap) {
  PathMetrics before, after;
  const std::string html = Render(nullptr, &before, &after);
  EXPECT_EQ(testing::CountOccurrences(html, "<svg class=\"heatmap\""), 0);
  EXPECT_EQ(testing::CountOccurrences(html, "<svg class=\"line-plot\""), 6);
  EXPECT_NE(html.find("<td>max overcut, mm</td><td>&mdash;</td><td>&mdash;</td>"),
            std::string::npos);
}

}  // namespace
}  // namespace tpopt
