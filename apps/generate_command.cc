// tpopt generate: a flank path from a ruled surface, as a CAM system would
// write it, optionally with a U/V mismatch and axis noise.
#include <cstdio>

#include "apps/commands.h"
#include "apps/exit_codes.h"
#include "apps/flags.h"
#include "apps/job_io.h"
#include "apps/options_from_flags.h"
#include "model/io/json_io.h"
#include "model/path/path_generator.h"

namespace tpopt {

int RunGenerate(const Invocation&) {
  Status s = Require(FLAGS_surface, "surface");
  if (s.ok()) s = Require(FLAGS_out, "out");
  if (s.ok()) s = CheckGcodeFlags();
  FlankPathOptions options;
  if (s.ok()) s = FlankPathOptionsFromFlags(&options);
  if (!s.ok()) return ReportFailure("generate", s);
  RuledSurface surface;
  Machine machine;
  ToolPath path;
  s = LoadRuledSurface(FLAGS_surface, &surface, nullptr);
  if (s.ok()) s = LoadMachine(FLAGS_machine, &machine);
  if (s.ok()) s = GenerateFlankPath(surface, options, &path);
  if (s.ok()) s = SaveToolPath(FLAGS_out, machine, path);
  if (!s.ok()) return ReportFailure("generate", s);
  if (!FLAGS_quiet) {
    std::fprintf(stderr, "tpopt generate: wrote %zu poses to %s\n", path.poses.size(),
                 FLAGS_out.c_str());
  }
  return kExitSuccess;
}

}  // namespace tpopt
