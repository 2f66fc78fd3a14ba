// The axes of a lead-in or lead-out: the cut's rotary motion continued.
//
// CAM writes a lead beyond the surface's ends with the end pose's axis, so
// the rotary axes stop dead where the cut turns them and the junction is
// the path's peak d2A/ds2 or d2C/ds2. The solve cannot mend that itself:
// it measures a lead's steps by the programmed tips, which it may slide
// along their line, and the moved end pose makes the junction's real step
// another (issue 16, seed 20: d2A 89 x the clean SPO path's there). The
// leads cut air, so their axes are set after the solve: A and C of each
// lead pose are the cut's, continued at the rate of the cut's first move
// from the junction, over the tips' arc length as the controller moves
// them, so that no step of d2 is left at the junction or along the lead;
// or at a fraction of that rate, and the tips along the cut's motion too
// (the pipeline tries each, solver/smooth/smoothing_pipeline.cc).
#ifndef TPOPT_SOLVER_LEAD_CONTINUATION_H_
#define TPOPT_SOLVER_LEAD_CONTINUATION_H_

#include <vector>

#include "model/machine/machine.h"
#include "model/path/tool_path.h"

namespace tpopt {

// How a lead continues the cut.
struct LeadContinuation {
  // A and C at this fraction of the cut's rates (1: the cut's own; 0: the
  // junction's axis held, as CAM writes a lead).
  double rate_fraction = 1.0;
  // The tips too: along the cut's first move from the junction, at the
  // lead's own steps, where each stays within band_mm of its programmed
  // place (a lead continuing the cut sweeps the surface's extension; one
  // turned on the programmed line may cut into the end ruling's top).
  // Otherwise the tips stay.
  bool along_cut = false;
  double band_mm = 1.0;
  // No continued axis leaves this cone round the programmed axis, degrees.
  double cone_deg = 12.0;
};

// Sets the poses of `path` flagged in `lead` (a lead-in or lead-out beyond
// the surface's ends, model/path/rail_projection.h PosesBeyondRailEnds) to
// the continuation of the cut each stretch of them joins by a feed move, as
// `how` says. A stretch is left as it is where the cut's first move is
// shorter than a micrometre or absent, where it is reached only through a
// held pose or joins cuts on both sides, where a continued axis would leave
// the cone round the programmed axis (`programmed`, same poses) or lie
// within 1 deg of the pole, where a continued tip would leave its band, or
// where the path would then leave the machine's travel. Returns how many
// poses were set. Precondition: lead and programmed have one entry a pose
// of `path`.
int ContinueLeads(const Machine& machine, const std::vector<bool>& lead,
                  const ToolPath& programmed, const LeadContinuation& how, ToolPath* path);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_LEAD_CONTINUATION_H_
