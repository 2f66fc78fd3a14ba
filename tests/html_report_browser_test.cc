// The HTML report in a real browser: headless Chromium loads what
// `tpopt smooth --html` wrote, with no console error, and the plots hold
// drawn geometry. Skips when Chromium is not installed (.ci/install-deps
// installs it, so CI runs it).
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/test_util.h"

namespace tpopt {
namespace {

using testing::RunCommand;
using testing::SourcePath;
using testing::TempDir;

// Runs in the page once it has loaded: records script errors and console
// errors, measures what the plots drew (a path's bounding box is empty
// unless the browser parsed its d into geometry), and leaves the results as
// JSON in <pre id="probe"> for --dump-dom to carry out.
constexpr char kProbe[] = R"(<script>
window.probeErrors = [];
window.addEventListener('error', e => window.probeErrors.push(String(e.message)));
const originalConsoleError = console.error;
console.error = (...args) => { window.probeErrors.push(args.join(' '));
                               originalConsoleError(...args); };
window.addEventListener('load', () => {
  let series = 0, drawn = 0;
  for (const path of document.querySelectorAll('svg.line-plot path.series')) {
    ++series;
    const box = path.getBBox();
    if ((path.getAttribute('d') || '').length > 0 && box.width > 1 && box.height > 0) ++drawn;
  }
  let visibleCells = 0;
  for (const cell of document.querySelectorAll('svg.heatmap g.cells rect')) {
    const box = cell.getBoundingClientRect();
    if (box.width > 0 && box.height > 0) ++visibleCells;
  }
  const probe = document.createElement('pre');
  probe.id = 'probe';
  probe.textContent = JSON.stringify({
    plots: document.querySelectorAll('svg.line-plot').length,
    heatmaps: document.querySelectorAll('svg.heatmap').length,
    series, drawn, visibleCells,
    cells: document.querySelectorAll('svg.heatmap g.cells rect').length,
    rows: document.querySelectorAll('table.summary tr').length,
    errors: window.probeErrors});
  document.body.appendChild(probe);
});
</script>
)";

bool HaveChromium() { return RunCommand("command -v chromium").exit_code == 0; }

// Headless Chromium with a private profile; root needs --no-sandbox.
std::string Chromium(const TempDir& dir, const std::string& args) {
  return "timeout 60 chromium --headless --no-sandbox --disable-gpu --no-first-run "
         "--user-data-dir=" + dir.File("profile") + " --enable-logging=stderr --v=0 " + args;
}

// The report of a spline smoothing of a distorted 60-pose blade path.
std::string WriteReport(const TempDir& dir) {
  const std::string blade = SourcePath("data/surfaces/impeller_blade.json");
  const std::string cam = dir.File("cam.cls"), html = dir.File("report.html");
  auto r = RunCommand(testing::TpoptBinary() + " generate --surface=" + blade +
                      " --cutter_radius=4 --poses=60 --uv_distortion=0.03 --axis_noise_deg=0.3"
                      " --out=" + cam);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = RunCommand(testing::TpoptBinary() + " smooth --mode=spline --quiet --in=" + cam +
                 " --out=" + dir.File("out.cls") + " --surface=" + blade + " --machine=" +
                 SourcePath("data/machines/linuxcnc_xyzac_trt_sim.json") +
                 " --samples_u=50 --samples_v=6 --html=" + html);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return html;
}

// `html` with the probe as the first thing in <head>, so it sees every
// error the page's own content could raise.
std::string WithProbe(const TempDir& dir, const std::string& html) {
  std::string page = testing::ReadFileText(html);
  const size_t head = page.find("<head>");
  EXPECT_NE(head, std::string::npos);
  page.insert(head + 6, kProbe);
  const std::string probed = dir.File("probed.html");
  std::ofstream(probed) << page;
  return probed;
}

class HtmlReportBrowserTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!HaveChromium()) {
      GTEST_SKIP() << "chromium is not installed (apt-get install chromium, as .ci/install-deps "
                      "does): the HTML report was not loaded in a browser";
    }
    html_ = WriteReport(dir_);
  }

  TempDir dir_;
  std::string html_;
};

TEST_F(HtmlReportBrowserTest, ChromiumLoadsTheReportAndDrawsEveryPlot) {
  const auto r = RunCommand(Chromium(dir_, "--dump-dom file://" + WithProbe(dir_, html_)));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const size_t open = r.output.find("<pre id=\"probe\">"), close = r.output.find("</pre>", open);
  ASSERT_NE(open, std::string::npos) << "the probe did not run:\n" << r.output;
  const nlohmann::json probe = nlohmann::json::parse(r.output.substr(open + 16, close - open - 16));
  EXPECT_EQ(probe["errors"], nlohmann::json::array()) << probe.dump();
  EXPECT_EQ(r.output.find("Uncaught"), std::string::npos) << r.output;
  // A and C angle, velocity, acceleration; before and after on each.
  EXPECT_EQ(probe["plots"], 6);
  EXPECT_EQ(probe["series"], 12);
  EXPECT_EQ(probe["drawn"], 12) << probe.dump();
  EXPECT_EQ(probe["heatmaps"], 2);
  EXPECT_EQ(probe["cells"], 2 * 50 * 6);
  EXPECT_EQ(probe["visibleCells"], probe["cells"]);
  EXPECT_GT(probe["rows"].get<int>(), 10);
}

TEST_F(HtmlReportBrowserTest, ChromiumScreenshotsTheReport) {
  // Kept in the build folder for a person to look at.
  const std::string png = std::string(TPOPT_BUILD_DIR) + "/report.png";
  std::remove(png.c_str());
  const auto r = RunCommand(
      Chromium(dir_, "--window-size=1300,2000 --screenshot=" + png + " file://" + html_));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string image = testing::ReadFileText(png);
  ASSERT_GT(image.size(), 20000u) << "a blank page compresses to a few kB";
  EXPECT_EQ(image.substr(1, 3), "PNG");
}

}  // namespace
}  // namespace tpopt
