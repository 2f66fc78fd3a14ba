// The initial guess of high-accuracy mode with a surface: every cutting pose
// placed on the surface at its own contact ruling, instead of the spline of
// the noisy input.
//
// A CAM path carries axis noise and a U/V mismatch that leave its cutter
// tenths of a millimetre off the surface, and the spline method only
// smooths the angles within its tolerance, so the solve used to start as far
// off as the input and end in a local minimum (a gouge, or worse than its
// start). The surface is known, so each pose i is rebuilt exactly:
//   u_i  its contact ruling, the input's foot point on rail 0
//        (model/path/rail_projection.h; the u the Ceres problem ties it to),
//   h_i  the input's overhang of the tip below the floor (solver/spline/overhang.h),
//   the double-point-offset pose at u_i (model/path/path_generator.h) of a cutter
//   whose radius at the floor is the cutter's there, R + h_i tan(taper),
//   slid down its axis by h_i so the tip keeps the programmer's height.
// DPO is a smooth function of u, so the guess is smooth in the contact's arc
// length, which is the abscissa of the problem's derivatives.
// A pose whose contact lies beyond an end of rail 0 (lead-in and lead-out
// moves in the air) is not on the surface: it follows the nearest pose on
// the surface rigidly (the same rotation and translation), so a straight
// lead stays straight and joins its cut as programmed. Rapid and link
// targets, and every pose of a path with no pose on the surface, keep the
// input's place.
#ifndef TPOPT_SOLVER_SURFACE_PLACEMENT_H_
#define TPOPT_SOLVER_SURFACE_PLACEMENT_H_

#include "model/cutter/cutter.h"
#include "model/geometry/ruled_surface.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

// A pose whose foot on rail 0 lies more than this beyond the rail's end,
// mm along the end tangent, is off the surface (the end pose of a cut sits
// within its axis noise times the cutter radius of it, a few hundredths;
// a lead move goes on by its step, 0.5 mm and more).
constexpr double kBeyondRailEndMm = 0.1;

// True when `pose`'s axis point level with C1(u) (u: its contact ruling on
// rail 0, as model/path/rail_projection.h finds it) lies beyond rail 0's end by
// more than kBeyondRailEndMm: a lead-in or lead-out pose in the air.
bool BeyondRailEnd(const RuledSurface& surface, const ToolPose& pose, double u);

// Writes the placed path to `out` (same poses, feeds and flags as `input`).
// Fails naming u where the surface normal vanishes.
Status PlaceOnSurface(const ToolPath& input, const RuledSurface& surface, const Cutter& cutter,
                      ToolPath* out);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_SURFACE_PLACEMENT_H_
