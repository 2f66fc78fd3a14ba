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
// them, so that no step of d2 is left at the junction or along the lead.
#ifndef TPOPT_SOLVER_LEAD_CONTINUATION_H_
#define TPOPT_SOLVER_LEAD_CONTINUATION_H_

#include <vector>

#include "model/machine/machine.h"
#include "model/path/tool_path.h"

namespace tpopt {

// Sets the axes of the poses of `path` flagged in `lead` (a lead-in or
// lead-out beyond the surface's ends, model/path/rail_projection.h
// PosesBeyondRailEnds) to the continuation of the cut each stretch of them
// joins by a feed move, at `rate_fraction` of the cut's rates (1: the
// cut's own; 0: the junction's axis held, as CAM writes a lead); the tips
// stay. A stretch is left as it is where the
// cut's first move is shorter than a micrometre or absent, where it is
// reached only through a held pose or joins cuts on both sides, where a
// continued axis would leave `cone_deg` of the programmed axis
// (`programmed`, same poses) or lie within 1 deg of the pole, or where the
// path would then leave the machine's travel. Returns how many poses were
// set. Precondition: lead and programmed have one entry a pose of `path`.
int ContinueLeadAxes(const Machine& machine, const std::vector<bool>& lead,
                     const ToolPath& programmed, double cone_deg, double rate_fraction,
                     ToolPath* path);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_LEAD_CONTINUATION_H_
