// Output resampling: natural cubic splines through the tip (x, y, z) and
// the rotary joints (A, C, unwrapped) of each cutting run, over the tip's
// arc length, sampled again at a uniform step no longer than `step_mm`.
// Spline in the joints rather than in the axis vector so that the rotaries
// move smoothly between the new poses too. Rapids, links and the poses they
// reach are kept as they are; each run keeps its first and last pose exactly.
#ifndef TPOPT_SOLVER_RESAMPLE_H_
#define TPOPT_SOLVER_RESAMPLE_H_

#include <string>

#include "model/machine/machine.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

struct ResampleOptions {
  // Largest arc-length step between output poses, mm. > 0.
  double step_mm = 0.5;
  bool IsValid(std::string* why) const;
};

Status ResamplePath(const ToolPath& in, const Machine& machine, const ResampleOptions& options,
                    ToolPath* out);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_RESAMPLE_H_
