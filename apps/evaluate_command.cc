// tpopt evaluate: metrics of a path, no output path.
#include <cstdio>

#include "apps/commands.h"
#include "apps/controller_run.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/huge_page_malloc.h"
#include "apps/job_io.h"
#include "apps/options_from_flags.h"
#include "apps/picture_outputs.h"
#include "apps/progress_display.h"
#include "apps/report.h"
#include "apps/version.h"
#include "model/io/json_io.h"

namespace tpopt {
namespace {

Status TravelCheck(const Job& job) {
  std::vector<JointVector> joints;
  Status s = job.machine.AssignJoints(job.path, &joints);
  if (s.ok()) s = job.machine.CheckTravel(job.path, joints);
  return s;
}

}  // namespace

int RunEvaluate(const Invocation& invocation) {
  Status s = Require(FLAGS_in, "in");
  if (s.ok()) s = Require(FLAGS_report, "report");
  if (s.ok()) s = CheckGcodeFlags();
  if (s.ok()) s = CheckPartSetupFlag();
  if (s.ok()) s = CheckPictureFlags();
  DeviationOptions deviation_options;
  MotionOptions motion_options;
  if (s.ok()) s = MetricOptionsFromFlags(&deviation_options, &motion_options);
  if (s.ok()) {
    s = InterpolationFromFlags(FLAGS_in, FLAGS_gcode_in_style, &deviation_options.interpolation);
  }
  LinkMoveOptions links;
  if (s.ok()) s = LinkMoveOptionsFromFlags(&links);
  if (!s.ok()) return ReportFailure("evaluate", s);
  s = CheckOutputFolders({FLAGS_report, FLAGS_html, FLAGS_vtk});
  Job job;
  PathMetrics metrics;
  if (s.ok()) s = LoadJob(FLAGS_quiet, links, &job);
  deviation_options.cutter_per_tool = job.cutter_per_tool;
  if (s.ok()) {
    ProgressDisplay progress(stderr, "tpopt evaluate", !FLAGS_quiet, FLAGS_progress_after_s);
    progress.SetStage("evaluating deviation and motion");
    s = EvaluatePath(job.path, job.machine, job.surface_or_null(), job.cutter, deviation_options,
                     motion_options, &metrics);
    if (!s.ok()) s = Status::Error(FLAGS_in + ": " + s.message());
  }
  if (!s.ok()) return ReportFailure("evaluate", s);
  nlohmann::json report = MetricsJson(metrics);
  report["tpopt_version"] = kTpoptVersion;
  report["huge_page_malloc"] = HugePageMallocActive();
  report["command"] = invocation.command_line;
  report["input_file"] = FLAGS_in;
  report["surface"] = FLAGS_surface;
  if (job.surface_cad) report["surface_cad"] = CadInfoJson(*job.surface_cad);
  report["machine"] = job.machine.name;
  report["cutter"] = {{"radius_mm", job.cutter.radius_mm},
                      {"flute_length_mm", job.cutter.flute_length_mm},
                      {"per_tool", job.cutter_per_tool}};
  report["interpolation"] = InterpolationName(deviation_options.interpolation);
  report["poses_in"] = metrics.poses;
  report["poses_out"] = metrics.poses;
  report["solve_time_s"] = 0.0;
  report["iterations"] = 0;
  if (job.controller) {
    report["controller"] = ControllerRunJson(*job.controller, metrics.motion.planner_time_s);
  }
  // What `tpopt smooth` refuses the path for, said here too: the first pose
  // outside an axis's travel, as smooth names it.
  const Status travel = TravelCheck(job);
  report["fits_travel"] = travel.ok();
  if (!travel.ok()) report["travel"] = travel.message();
  s = WriteReport(FLAGS_report, report);
  if (s.ok()) {
    // The file name alone labels the plots: a folder path would not fit the legend.
    const std::string name = FLAGS_in.substr(FLAGS_in.find_last_of('/') + 1);
    s = WritePictures("tpopt evaluate of " + FLAGS_in, invocation.command_line,
                      {{name, &job.path, &metrics}}, job);
  }
  if (!s.ok()) return ReportFailure("evaluate", s);
  if (!FLAGS_quiet) std::printf("%s", Summary(FLAGS_in, metrics).c_str());
  if (!travel.ok()) {
    std::fprintf(stderr, "tpopt evaluate: %s: %s (tpopt smooth refuses it)\n", FLAGS_in.c_str(),
                 travel.message().c_str());
  }
  return kExitSuccess;
}

}  // namespace tpopt
