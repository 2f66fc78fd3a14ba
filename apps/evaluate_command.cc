// tpopt evaluate: metrics of a path, no output path.
#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/inputs.h"
#include "apps/report.h"
#include "model/json_io.h"

namespace tpopt {

int RunEvaluate(const Invocation& invocation) {
  Status s = Require(FLAGS_in, "in");
  if (s.ok()) s = Require(FLAGS_report, "report");
  DeviationOptions deviation_options;
  deviation_options.samples_u = FLAGS_samples_u;
  deviation_options.samples_v = FLAGS_samples_v;
  MotionOptions motion_options;
  motion_options.default_feed_mm_per_min = FLAGS_feed;
  std::string why;
  if (s.ok() && !deviation_options.IsValid(&why)) s = Status::Error(why);
  if (s.ok() && !motion_options.IsValid(&why)) s = Status::Error(why);
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt evaluate: %s\n", s.message().c_str());
    return kExitUsage;
  }
  ToolPath path;
  RuledSurface surface;
  Machine machine;
  Cutter cutter;
  PathMetrics metrics;
  const bool has_surface = !FLAGS_surface.empty();
  s = LoadToolPath(FLAGS_in, FLAGS_quiet, &path);
  if (s.ok() && has_surface) s = ReadSurfaceJson(FLAGS_surface, &surface);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &machine);
  if (s.ok()) {
    s = ResolveCutter(path, has_surface ? &surface : nullptr, FLAGS_cutter_radius,
                      FLAGS_flute_length, &cutter);
  }
  if (s.ok()) {
    s = EvaluatePath(path, machine, has_surface ? &surface : nullptr, cutter, deviation_options,
                     motion_options, &metrics);
    if (!s.ok()) s = Status::Error(FLAGS_in + ": " + s.message());
  }
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt evaluate: %s\n", s.message().c_str());
    return kExitBadInput;
  }
  nlohmann::json report = MetricsJson(metrics);
  report["tpopt_version"] = "0.1.0";
  report["command"] = invocation.command_line;
  report["input_file"] = FLAGS_in;
  report["surface"] = FLAGS_surface;
  report["machine"] = machine.name;
  report["cutter"] = {{"radius_mm", cutter.radius_mm}, {"flute_length_mm", cutter.flute_length_mm}};
  report["poses_in"] = metrics.poses;
  report["poses_out"] = metrics.poses;
  report["solve_time_s"] = 0.0;
  report["iterations"] = 0;
  s = WriteReport(FLAGS_report, report);
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt evaluate: %s\n", s.message().c_str());
    return kExitBadInput;
  }
  if (!FLAGS_quiet) std::printf("%s", Summary(FLAGS_in, metrics).c_str());
  return kExitSuccess;
}

}  // namespace tpopt
