// The `--html` report: one self-contained HTML file (inline SVG, no script,
// no network) with the A and C motion against path length, the deviation
// map over the surface's (u, v), the summary table, the command line and
// the versions. See README.md "Pictures" for why the plots are SVG drawn
// here rather than a plotting library.
#ifndef TPOPT_APPS_HTML_REPORT_H_
#define TPOPT_APPS_HTML_REPORT_H_

#include <string>
#include <vector>

#include "apps/controller_run.h"
#include "model/machine/machine.h"
#include "model/eval/path_metrics.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct ReportedPath {
  std::string label;  // e.g. "before", "after"
  const ToolPath* path = nullptr;
  const PathMetrics* metrics = nullptr;  // evaluated on `path`
};

struct HtmlReportInputs {
  std::string title;         // e.g. "tpopt smooth"
  std::string command_line;  // as typed
  // One path (evaluate) or before and after (smooth), drawn overlaid.
  std::vector<ReportedPath> paths;
  const Machine* machine = nullptr;  // its limits are drawn on the plots
  double default_feed_mm_per_min = 1000.0;  // where a pose has none
  // What LinuxCNC's controller did with the last path's program, if known;
  // shown beside that path's predicted machining time.
  const ControllerRun* controller = nullptr;
};

// The whole page. Fails only when a path does not fit the machine (as
// Machine::AssignJoints), which its metrics would already have reported.
Status RenderHtmlReport(const HtmlReportInputs& inputs, std::string* html);

}  // namespace tpopt

#endif  // TPOPT_APPS_HTML_REPORT_H_
