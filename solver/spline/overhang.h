// The programmer's overhang of each pose: how far below the floor of the cut
// (rail 0) the tip sits along the tool axis, as the smoothers keep it
// (solver/smooth/cost/tip_height_cost.h, the spline method's tangency rebuild).
//
// A pose's own height h_i = (C1(u_i) - p_w_tip) . a_w carries the axis
// noise times the cutter radius (0.02 mm at 0.3 deg and R 4) and a tilted
// pose's R sin(tilt) (0.2 mm at 3 deg), while a run's median misses a
// deliberate change (a tip plunging along its axis). So the heights of each
// cutting run are fitted with the smoothest spline over the pose index that
// stays within kOverhangNoiseMm of every h_i (solver/spline/smoothing_spline.h):
// constant and linear overhangs come through exactly, noise and spikes of
// a few poses do not. A tip above the floor would leave the bottom of the
// ruling uncut, so it is brought down to the floor: the overhang is >= 0.
#ifndef TPOPT_SOLVER_OVERHANG_H_
#define TPOPT_SOLVER_OVERHANG_H_

#include <vector>

#include "model/geometry/bspline_curve.h"
#include "model/base/status.h"
#include "model/path/tool_path.h"

namespace tpopt {

constexpr double kOverhangNoiseMm = 0.25;

// Fills overhang_mm (one per pose of `path`, mm, >= 0: the tip below the
// floor) from the contact rulings u (one per pose) on `rail` (rail 0).
Status PoseOverhangs(const BSplineCurve& rail, const ToolPath& path,
                     const std::vector<double>& u,
                     std::vector<double>* overhang_mm);

}  // namespace tpopt

#endif  // TPOPT_SOLVER_OVERHANG_H_
