// tpopt generate: a flank path from a ruled surface, as a CAM system would
// write it, optionally with a U/V mismatch and axis noise.
#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/job_io.h"
#include "model/json_io.h"
#include "model/path_generator.h"

namespace tpopt {

int RunGenerate(const Invocation&) {
  Status s = Require(FLAGS_surface, "surface");
  if (s.ok()) s = Require(FLAGS_out, "out");
  if (s.ok()) s = CheckGcodeFlags();
  FlankPathOptions options;
  if (FLAGS_strategy == "spo") {
    options.strategy = FlankStrategy::kSinglePointOffset;
  } else if (FLAGS_strategy == "dpo") {
    options.strategy = FlankStrategy::kDoublePointOffset;
  } else if (s.ok()) {
    s = Status::Usage("--strategy=" + FLAGS_strategy + " must be spo or dpo");
  }
  if (s.ok() && FLAGS_cutter_radius == 0.0) s = Status::Usage("--cutter_radius is required");
  options.cutter_radius_mm = FLAGS_cutter_radius;
  options.poses = FLAGS_poses;
  options.feed_mm_per_min = FLAGS_feed;
  options.uv_distortion = FLAGS_uv_distortion;
  options.distortion_center = FLAGS_distortion_center;
  options.distortion_width = FLAGS_distortion_width;
  options.axis_noise_deg = FLAGS_axis_noise_deg;
  options.noise_seed = static_cast<unsigned>(FLAGS_noise_seed);
  options.flute_length_mm = FLAGS_flute_length;
  std::string why;
  if (s.ok() && !options.IsValid(&why)) s = Status::Usage(why);
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt generate: %s\n", s.message().c_str());
    return ExitCodeOf(s);
  }
  RuledSurface surface;
  Machine machine;
  ToolPath path;
  s = LoadRuledSurface(FLAGS_surface, &surface, nullptr);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &machine);
  if (s.ok()) s = GenerateFlankPath(surface, options, &path);
  if (s.ok()) s = SaveToolPath(FLAGS_out, machine, path);
  if (!s.ok()) {
    std::fprintf(stderr, "tpopt generate: %s\n", s.message().c_str());
    return ExitCodeOf(s);
  }
  if (!FLAGS_quiet) {
    std::fprintf(stderr, "tpopt generate: wrote %zu poses to %s\n", path.poses.size(),
                 FLAGS_out.c_str());
  }
  return kExitSuccess;
}

}  // namespace tpopt
